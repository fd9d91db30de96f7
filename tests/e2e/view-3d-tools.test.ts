/**
 * The editor's tools on a 3D graph, in real Chromium: Export → GLSL and Shadertoy give the sphere
 * tracer (the same generator as `kleinflow glsl`) with the scene's values and the view's camera,
 * and glslangValidator accepts both; Export → SVG is disabled with its reason; while the camera
 * orbits the 3D pane renders at a reduced resolution and returns to full size once still; and
 * inspect mode explains a 3D pixel (and a press on a handle then never drags it), and in volume
 * mode says what the volume integration did along the ray. The pane is small and the render node cheap, as in
 * view-3d.test.ts (SwiftShader sphere-traces slowly).
 */
import { readFileSync } from 'node:fs';
import type { Page } from 'playwright-core';
import { describe, expect, it } from 'vitest';
import type { GraphDoc } from '../../nodes/graph/document.ts';
import { evaluateGraph } from '../../nodes/graph/evaluate.ts';
import { registry } from '../../nodes/types/index.ts';
import { explainPixel3d } from '../../shader-gen/space/explain-3d.ts';
import { explainVolumePixel3d } from '../../shader-gen/space/explain-volume-3d.ts';
import { standaloneShader } from '../../shader-gen/standalone.ts';
import { shadertoyWrapper, validateShaders } from '../shader-gen/support/glslang.ts';
import { appSessionForSuite } from './app-suite.ts';
import { nodeEl, waitRendered } from './editor-page.ts';
import { freePanePoint, handleCentres, open3dExample, openSmall3dPane } from './view-3d-page.ts';

const ID = 'fig11-sphere-inversion-fractal';
const SLOW = { timeout: 90_000 };

let page: Page;

const doc = () => page.evaluate(() => window.__kleinflow!.store.getState().doc) as Promise<GraphDoc>;

appSessionForSuite((s) => ({ page } = s), {
  open: openSmall3dPane,
  setupTimeout: 240_000,
  ready: async (p) => {
    await open3dExample(p, ID);
    // Cheap values for SwiftShader (never a recompile); a camera of the view's own, as after an orbit.
    await p.evaluate(() => {
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
  },
});

/** Opens the Export menu and returns its item named `name`. */
async function exportItem(name: RegExp) {
  await page.getByRole('button', { name: /^Export/ }).click();
  return page.getByRole('menuitem', { name });
}

async function exportText(name: RegExp): Promise<{ name: string; text: string }> {
  const item = await exportItem(name);
  const [download] = await Promise.all([page.waitForEvent('download'), item.click()]);
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

const drawnSize = () =>
  page.evaluate(() => {
    const v = window.__kleinflow!.viewport!;
    const canvas = document.querySelector<HTMLCanvasElement>('[data-testid="render-pane"] canvas')!;
    return { ...v.stats.renderSize, scale: v.stats.renderScale, canvas: [canvas.width, canvas.height] };
  });

describe('Dynamic resolution of the 3D pane', () => {
  it('an orbit drag draws smaller than the canvas; once still the picture is full size again', async () => {
    await waitRendered(page, 120_000);
    const still = await drawnSize();
    expect([still.width, still.height]).toEqual(still.canvas);
    // Record the size of every frame drawn during the drag (sampled each animation frame).
    await page.evaluate(() => {
      const w = window as unknown as { sizes: number[][]; sampling: boolean };
      w.sizes = [];
      w.sampling = true;
      const sample = () => {
        const { renderSize, renderScale } = window.__kleinflow!.viewport!.stats;
        w.sizes.push([renderSize.width, renderSize.height, renderScale]);
        if (w.sampling) requestAnimationFrame(sample);
      };
      sample();
    });
    const from = await freePanePoint(page);
    await page.mouse.move(from.x, from.y);
    await page.mouse.down();
    for (let i = 1; i <= 12; i++) {
      await page.mouse.move(from.x + 4 * i, from.y + 2 * i);
      await page.waitForTimeout(60);
    }
    await page.mouse.up();
    const sizes = await page.evaluate(() => {
      const w = window as unknown as { sizes: number[][]; sampling: boolean };
      w.sampling = false;
      return w.sizes;
    });
    const reduced = sizes.filter(([, , scale]) => scale < 1);
    expect(reduced.length).toBeGreaterThan(0);
    for (const [width, height] of reduced) {
      expect(width).toBeLessThan(still.canvas[0]);
      expect(height).toBeLessThan(still.canvas[1]);
    }
    // Still again: drawn at the canvas's size, and the status line says it is rendered.
    await expect
      .poll(async () => {
        const d = await drawnSize();
        return d.scale === 1 && d.width === d.canvas[0] && d.height === d.canvas[1];
      }, SLOW)
      .toBe(true);
    await waitRendered(page, 120_000);
    expect((await drawnSize()).scale).toBe(1);
  }, 240_000);
});

describe('Explain this pixel in 3D', () => {
  it('an Alt-click on the orbit shows the hit point and the word that maps it onto the seed', async () => {
    // A known camera looking at the orbit (the drag above moved the view's).
    await page.evaluate(() =>
      window.__kleinflow!.store.dispatchSilently({
        type: 'set-camera-3d',
        camera: { position: [5.25, -4.5, 3.75], target: [0, 0, 0.5], fovDeg: 41 },
      }),
    );
    await waitRendered(page, 120_000);
    const current = await doc();
    const scene = evaluateGraph(current, registry).scene3d!;
    const camera = current.camera3d ?? scene.camera;
    const b = (await page.getByTestId('render-pane').boundingBox())!;
    // A pixel (CSS point of the pane) whose ray and its neighbours hit images of the seed, away from handles.
    const handles = await handleCentres(page);
    // The pane's size as the app measures it (clientWidth/Height), for the same rays.
    const [w, h] = await page
      .getByTestId('render-pane')
      .evaluate((el) => [el.clientWidth, el.clientHeight] as const);
    const depthAt = (x: number, y: number) => {
      const e = explainPixel3d({ ...scene, camera }, w, h, x, h - y);
      return e.stop === 'seed' ? e.depth : -1;
    };
    // The depths a pixel around (a click lands within a pixel of the asked point).
    const around = (x: number, y: number) =>
      new Set([-1, 0, 1].flatMap((dx) => [-1, 0, 1].map((dy) => depthAt(x + dx, y + dy))));
    let found: { x: number; y: number; depths: Set<number> } | null = null;
    for (let y = 12; y < h - 12 && !found; y += 4)
      for (let x = 12; x < w - 12 && !found; x += 4) {
        if (handles.some(([hx, hy]) => Math.hypot(hx - b.x - x, hy - b.y - y) < 24)) continue;
        if (depthAt(x, y) < 1) continue;
        const depths = around(x, y);
        if ([...depths].every((d) => d >= 0)) found = { x, y, depths };
      }
    expect(found, `no orbit pixel in a ${w} × ${h} view through ${JSON.stringify(camera)}`).not.toBeNull();
    await page.keyboard.down('Alt');
    await page.mouse.click(b.x + found!.x, b.y + found!.y);
    await page.keyboard.up('Alt');
    const panel = page.getByTestId('inspect-panel');
    await panel.waitFor();
    const depth = Number(await panel.getByTestId('inspect-depth').textContent());
    expect(found!.depths.has(depth)).toBe(true);
    expect(await panel.textContent()).toContain('Hit point');
    expect(await panel.textContent()).toMatch(
      /mapped onto the orbit seed .* in \d+ steps?|on the orbit seed/,
    );
    const letters = panel.getByRole('list', { name: 'Word' }).getByRole('listitem');
    expect(await letters.count()).toBe(depth);
    if (depth > 0) expect(await letters.first().textContent()).toMatch(/inversion|Sphere/i);
    expect(await panel.getByTestId('inspect-gpu').textContent()).toContain('CPU tracer');
    await page.keyboard.press('Escape');
    await panel.waitFor({ state: 'detached' });

    // Inspect mode, as in 2D: a press on a handle never drags it; a click there explains the pixel.
    await page.getByRole('button', { name: 'Inspect', exact: true }).click();
    const nodesBefore = JSON.stringify((await doc()).nodes);
    const knobCentre = async () => {
      const k = (await page.locator('[data-handle]').first().boundingBox())!;
      return [k.x + k.width / 2, k.y + k.height / 2] as const;
    };
    const [kx, ky] = await knobCentre();
    await page.mouse.move(kx, ky);
    await page.mouse.down();
    await page.mouse.move(kx + 30, ky + 20, { steps: 5 });
    await page.mouse.up();
    expect(JSON.stringify((await doc()).nodes)).toBe(nodesBefore);
    const [cx, cy] = await knobCentre();
    await page.mouse.click(cx, cy);
    await panel.waitFor();
    expect(JSON.stringify((await doc()).nodes)).toBe(nodesBefore);
    await page.keyboard.press('Escape');
    await panel.waitFor({ state: 'detached' });
    await page.keyboard.press('Escape');
    expect(
      await page.getByRole('button', { name: 'Inspect', exact: true }).getAttribute('aria-pressed'),
    ).toBe('false');
  }, 240_000);

  it('in volume mode the panel says what the volume integration did along the ray', async () => {
    const camera = { position: [5.25, -4.5, 3.75], target: [0, 0, 0.5], fovDeg: 41 } as const;
    await page.evaluate((cam) => {
      const store = window.__kleinflow!.store;
      store.dispatchSilently({
        type: 'set-params',
        patches: [{ nodeId: 'render', params: { render: 'volume', volumeSteps: 24 } }],
      });
      store.dispatchSilently({
        type: 'set-camera-3d',
        camera: { position: [...cam.position], target: [...cam.target], fovDeg: cam.fovDeg },
      });
    }, camera);
    // The panel is the CPU's (no GPU frame is read): wait for the edited document, not the picture.
    await expect.poll(async () => evaluateGraph(await doc(), registry).scene3d?.volume?.steps, SLOW).toBe(24);
    const current = await doc();
    const scene = evaluateGraph(current, registry).scene3d!;
    // The node shows the volume's settings, not the sphere tracer's (which would change nothing).
    const renderNode = nodeEl(page, 'render');
    await renderNode.getByRole('combobox', { name: 'volume palette' }).waitFor();
    expect(await renderNode.getByRole('combobox', { name: 'colouring' }).count()).toBe(0);
    expect(await renderNode.getByRole('textbox', { name: 'reflections' }).count()).toBe(0);
    const view = { ...scene, camera: current.camera3d ?? scene.camera };
    const b = (await page.getByTestId('render-pane').boundingBox())!;
    const handles = await handleCentres(page);
    const [w, h] = await page
      .getByTestId('render-pane')
      .evaluate((el) => [el.clientWidth, el.clientHeight] as const);
    const at = (x: number, y: number) => explainVolumePixel3d(view, w, h, x, h - y);
    // A pixel whose ray, and its neighbours' (a click lands within a pixel), crosses nested mirrors;
    // tried from the pane's centre out, where the clusters are (each try prepares a trace: ~10 ms).
    const candidates: [number, number][] = [];
    for (let y = 12; y < h - 12; y += 4) for (let x = 12; x < w - 12; x += 4) candidates.push([x, y]);
    candidates.sort(
      (p, q) => Math.hypot(p[0] - w / 2, p[1] - h / 2) - Math.hypot(q[0] - w / 2, q[1] - h / 2),
    );
    let found: { x: number; y: number; samples: Set<number> } | null = null;
    for (const [x, y] of candidates) {
      if (handles.some(([hx, hy]) => Math.hypot(hx - b.x - x, hy - b.y - y) < 24)) continue;
      if (at(x, y).deepest < 2) continue;
      const around = [-1, 0, 1].flatMap((dx) => [-1, 0, 1].map((dy) => at(x + dx, y + dy)));
      if (around.every((e) => e.deepest >= 2)) {
        found = { x, y, samples: new Set(around.map((e) => e.samples)) };
        break;
      }
    }
    expect(found, `no nested pixel in a ${w} × ${h} view`).not.toBeNull();
    await page.keyboard.down('Alt');
    await page.mouse.click(b.x + found!.x, b.y + found!.y);
    await page.keyboard.up('Alt');
    const panel = page.getByTestId('inspect-panel');
    await panel.waitFor();
    const samples = Number(await panel.getByTestId('inspect-samples').textContent());
    expect(found!.samples.has(samples)).toBe(true);
    const text = (await panel.textContent())!;
    expect(text).toContain('of 24');
    expect(text).not.toContain('Hit point');
    expect(text).toMatch(/crosses the volume in \d+ samples?, down to nesting depth \d+/);
    expect(Number(await panel.getByTestId('inspect-depth').textContent())).toBeGreaterThanOrEqual(2);
    const runs = panel.getByRole('list', { name: 'Depth along the ray' }).getByRole('listitem');
    expect(await runs.count()).toBeGreaterThan(1);
    expect(await runs.first().textContent()).toMatch(/^depth \d+.*× \d+ samples?/);
    expect(await panel.getByTestId('inspect-colour').textContent()).toMatch(/^#[0-9a-f]{6}$/);
    expect(await panel.getByTestId('inspect-gpu').textContent()).toContain('CPU volume renderer');
    await page.keyboard.press('Escape');
    await panel.waitFor({ state: 'detached' });
    await page.evaluate(() =>
      window.__kleinflow!.store.dispatchSilently({
        type: 'set-params',
        patches: [{ nodeId: 'render', params: { render: 'surface' } }],
      }),
    );
  }, 240_000);
});
