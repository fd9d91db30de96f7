/**
 * `kleinflow render` and `kleinflow glsl` on a 3D graph, through the real executable: the PNG is
 * the CPU sphere tracer's picture (pixel for pixel what renderScene3d gives) with the graph inside;
 * the GLSL is the baked sphere-tracing shader (valid GLSL ES), `--shadertoy` its mainImage; a 3D
 * graph with --time is refused in one line.
 */
import { readFileSync } from 'node:fs';
import { join } from 'node:path';
import { describe, expect, it } from 'vitest';
import { compile3d } from '../../shader-gen/space/compile-3d.ts';
import { renderScene3d } from '../../shader-gen/space/render-3d.ts';
import { decodePng, readPngText } from '../../src/io/png.ts';
import { shadertoyWrapper, validateShaders } from '../shader-gen/support/glslang.ts';
import { cliTempDir, evaluateFile, ROOT, runCli, runCliOk } from './run-cli.ts';

const INDRA = join(ROOT, 'examples/3d/indras-bubbles.kleinflow.json');

const dir = cliTempDir('kleinflow-render3d-');
const sceneOf = (path: string) => evaluateFile(path).scene3d!;

describe('kleinflow render / glsl on a 3D graph', () => {
  it('renders the sphere-traced picture with the graph embedded', () => {
    const out = join(dir, 'indra.png');
    const run = runCliOk(['render', INDRA, '-o', out, '--size', '48x36', '--samples', '1']);
    expect(run.stdout).toMatch(/^wrote .*indra\.png \(48×36, 1 samples\/px/);
    const bytes = readFileSync(out);
    const png = decodePng(bytes);
    const expected = renderScene3d(sceneOf(INDRA), 48, 36, { samples: 1 });
    expect(Buffer.from(png.data)).toEqual(Buffer.from(expected.data));
    expect(readPngText(bytes)?.kleinflow).toContain('render-3d');
  });

  it('refuses --time on a 3D graph in one line', () => {
    const run = runCli(['render', INDRA, '-o', join(dir, 'x.png'), '--time', '1']);
    expect(run.status).not.toBe(0);
    expect(run.stderr.split('\n')[0]).toMatch(/--time needs a 2D graph/);
  });

  it('prints the baked sphere-tracing shader and its Shadertoy version, both valid', () => {
    const glsl = runCli(['glsl', INDRA]);
    expect(glsl.status).toBe(0);
    expect(glsl.stdout).toBe(compile3d(sceneOf(INDRA), { bake: true }).source);
    const toy = runCli(['glsl', INDRA, '--shadertoy']);
    expect(toy.status).toBe(0);
    expect(toy.stdout).toContain('void mainImage(out vec4 fragColor, in vec2 fragCoord)');
    const probe = runCli(['glsl', INDRA, '--probe']);
    expect(probe.stdout).toContain('outProbe');
    const results = validateShaders([
      { name: 'cli-3d', source: glsl.stdout, stage: 'frag' },
      { name: 'cli-3d-probe', source: probe.stdout, stage: 'frag' },
      { name: 'cli-3d-toy', source: shadertoyWrapper(toy.stdout), stage: 'frag' },
    ]);
    expect([...results.values()].flat()).toEqual([]);
  });
});
