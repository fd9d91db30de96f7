/**
 * `kleinflow mesh` read by an independent slicer: the Fig. 36 quasi-sphere as 3MF, opened by
 * PrusaSlicer (`prusa-slicer --info`, Debian's prusa-slicer; `npm test` installs it) as one
 * manifold part with the mesh's triangles, as large as the success line says — 1 mm per scene unit
 * by default, a 60 mm longest side with --print-size 60. PrusaSlicer 2.5 ignores 3MF colour groups
 * (it paints its own); the colours are checked by the other readers (cli/mesh.test.ts,
 * src/io/three-mf.test.ts, src/io/glb.test.ts).
 */
import { spawnSync } from 'node:child_process';
import { mkdtempSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { afterAll, describe, expect, it } from 'vitest';
import { ROOT, runCli } from './run-cli.ts';

const FIG36 = join(ROOT, 'examples/3d/fig36-colour-print-quasi-sphere.kleinflow.json');
const dir = mkdtempSync(join(tmpdir(), 'kleinflow-prusa-'));
afterAll(() => rmSync(dir, { recursive: true, force: true }));

/** `prusa-slicer --info FILE`'s "key = value" lines (its log lines have no " = "). */
function slicerInfo(file: string): Record<string, string> {
  const r = spawnSync('prusa-slicer', ['--info', file], { encoding: 'utf8', timeout: 60_000 });
  if (r.error)
    throw new Error(`prusa-slicer could not run (${r.error.message}): apt-get install prusa-slicer`);
  expect(r.status, r.stderr).toBe(0);
  return Object.fromEntries(
    [...r.stdout.matchAll(/^(\w+) = +(.*)$/gm)].map((m) => [m[1]!, m[2]!.trim()] as [string, string]),
  );
}

/** Meshes Fig. 36 to `file` and returns the success line's triangle count and size in mm. */
function mesh(file: string, ...options: string[]) {
  const r = runCli(['mesh', FIG36, '--out', join(dir, file), '--resolution', '16', ...options]);
  expect(r.status, r.stderr).toBe(0);
  const said = /\((\d+) triangles.*\): ([\d.]+) × ([\d.]+) × ([\d.]+) mm/.exec(r.stdout);
  expect(said, r.stdout).not.toBeNull();
  return { triangles: Number(said![1]), size: said!.slice(2, 5).map(Number), stdout: r.stdout };
}

const sizes = (info: Record<string, string>) => ['size_x', 'size_y', 'size_z'].map((k) => Number(info[k]));

/** The slicer's size is the success line's, which is written to a tenth of a millimetre. */
function expectSaidSize(info: Record<string, string>, said: readonly number[]) {
  for (const [a, s] of sizes(info).entries()) expect(Math.abs(s - said[a]!)).toBeLessThanOrEqual(0.051);
}

describe('kleinflow mesh read by PrusaSlicer', () => {
  it('opens the Fig. 36 3MF with --print-size 60 as one manifold 60 mm part with the mesh’s triangles', () => {
    const { triangles, size } = mesh('fig36-60mm.3mf', '--print-size', '60');
    const info = slicerInfo(join(dir, 'fig36-60mm.3mf'));
    expect(info.manifold).toBe('yes');
    expect(Number(info.number_of_parts)).toBe(1);
    expect(Number(info.number_of_facets)).toBe(triangles);
    expect(Math.max(...sizes(info))).toBeCloseTo(60, 3);
    expectSaidSize(info, size);
    expect(Number(info.volume)).toBeGreaterThan(0);
  });

  it('reads one scene unit as 1 mm without --print-size, the size the success line says', () => {
    const { triangles, size, stdout } = mesh('fig36.3mf');
    expect(stdout).toMatch(/; --print-size 60 for a 60 mm print/);
    const info = slicerInfo(join(dir, 'fig36.3mf'));
    expect(info.manifold).toBe('yes');
    expect(Number(info.number_of_facets)).toBe(triangles);
    // The quasi-sphere's sphere has radius 1.5: a speck of about 1.6 mm.
    expect(Math.max(...sizes(info))).toBeLessThan(2);
    expectSaidSize(info, size);
  });
});
