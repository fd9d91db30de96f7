/**
 * `kleinflow mesh` through the real binary: the Fig. 26 quasi-sphere as binary STL that parses
 * back into a closed, consistently oriented mesh, progress on stderr; the same triangles with the
 * render's colours as GLB (Khronos-validated) and 3MF; --print-size scales the closed mesh to a
 * physical size (mm in STL, m in GLB) and the success line says it; an unbounded graph without
 * --bounds, a 2D graph and bad options are refused in one line. (PrusaSlicer reading the 3MF:
 * mesh-prusa-slicer.test.ts.)
 */
import { existsSync, readFileSync } from 'node:fs';
import { join } from 'node:path';
import { WebIO } from '@gltf-transform/core';
import { unzipSync } from 'fflate';
import { validateBytes } from 'gltf-validator';
import { describe, expect, it } from 'vitest';
import { readStl } from '../../src/io/stl.ts';
import { unmatchedEdges } from '../shader-gen/space/coloured-mesh.ts';
import { cliTempDir, ROOT, runCli } from './run-cli.ts';

const example3d = (name: string) => join(ROOT, `examples/3d/${name}.kleinflow.json`);
const dir = cliTempDir('kleinflow-mesh-');

/** Vertices are float32 in the file: edges are matched by their coordinates. */
function edgeCounts(triangles: ReturnType<typeof readStl>['triangles']) {
  const key = (v: readonly number[]) => v.join(',');
  const directed = new Map<string, number>();
  for (const t of triangles)
    for (let e = 0; e < 3; e++) {
      const k = `${key(t.vertices[e])}>${key(t.vertices[(e + 1) % 3])}`;
      directed.set(k, (directed.get(k) ?? 0) + 1);
    }
  let bad = 0;
  for (const [k, n] of directed) {
    const [a, b] = k.split('>');
    if (n !== 1 || directed.get(`${b}>${a}`) !== 1) bad++;
  }
  return { edges: directed.size, bad };
}

describe('kleinflow mesh', () => {
  it('writes the quasi-sphere as a closed, oriented binary STL, with progress on stderr', () => {
    const out = join(dir, 'quasi.stl');
    const r = runCli(['mesh', example3d('fig26-quasi-sphere'), '--out', out, '--resolution', '20']);
    expect(r.status).toBe(0);
    expect(r.stderr).toMatch(/meshing 25%/);
    const said = /wrote .* \((\d+) triangles, (\d+) vertices/.exec(r.stdout);
    expect(said).not.toBeNull();
    const { header, triangles } = readStl(new Uint8Array(readFileSync(out)));
    expect(header).toMatch(/^Kleinflow mesh/);
    expect(triangles.length).toBe(Number(said?.[1]));
    expect(triangles.length).toBeGreaterThan(500);
    const { edges, bad } = edgeCounts(triangles);
    expect(bad).toBe(0);
    expect(edges).toBe(3 * triangles.length);
  });

  it('writes the same closed mesh with the render’s colours as .glb and .3mf, chosen by the extension', async () => {
    const mesh = (file: string) => {
      const r = runCli(['mesh', example3d('fig26-quasi-sphere'), '--out', join(dir, file), '-r', '12']);
      expect(r.status).toBe(0);
      return Number(/\((\d+) triangles/.exec(r.stdout)?.[1]);
    };
    const stlCount = mesh('quasi.stl');
    expect(mesh('quasi.glb')).toBe(stlCount);
    expect(mesh('QUASI.3MF')).toBe(stlCount);

    const glb = new Uint8Array(readFileSync(join(dir, 'quasi.glb')));
    expect((await validateBytes(glb)).issues.numErrors).toBe(0);
    const primitive = (await new WebIO().readBinary(glb)).getRoot().listMeshes()[0]!.listPrimitives()[0]!;
    const indices = [...primitive.getIndices()!.getArray()!];
    expect(indices.length).toBe(3 * stlCount);
    expect(unmatchedEdges(indices)).toBe(0);
    // The quasi-sphere is coloured by depth on the wheel: many colours, none of them black.
    const rgb = primitive.getAttribute('COLOR_0')!.getArray()!;
    const distinct = new Set<string>();
    for (let v = 0; v < rgb.length; v += 3) {
      expect(Math.max(rgb[v]!, rgb[v + 1]!, rgb[v + 2]!)).toBeGreaterThan(0.1);
      distinct.add(`${rgb[v]},${rgb[v + 1]},${rgb[v + 2]}`);
    }
    expect(distinct.size).toBeGreaterThan(3);

    const model = new TextDecoder().decode(
      unzipSync(readFileSync(join(dir, 'QUASI.3MF')))['3D/3dmodel.model'],
    );
    const colours = model.match(/<m:color color="#[0-9A-F]{6}"\/>/g) ?? [];
    expect(colours.length).toBeGreaterThan(3);
    const triangles = [
      ...model.matchAll(
        /<triangle v1="(\d+)" v2="(\d+)" v3="(\d+)" pid="1" p1="(\d+)" p2="(\d+)" p3="(\d+)"\/>/g,
      ),
    ];
    expect(triangles.length).toBe(stlCount);
    expect(triangles.flatMap((t) => t.slice(4, 7).map(Number)).every((p) => p < colours.length)).toBe(true);
    expect(unmatchedEdges(triangles.flatMap((t) => t.slice(1, 4).map(Number)))).toBe(0);
  });

  it('scales to --print-size: a closed STL 60 mm along its longest side, the GLB 0.06 m, as the line says', async () => {
    const out = join(dir, 'quasi-60.stl');
    const r = runCli(['mesh', example3d('fig26-quasi-sphere'), '-o', out, '-r', '12', '--print-size', '60']);
    expect(r.status).toBe(0);
    expect(r.stdout).toMatch(/voxels\): [\d.]+ × 60\.0 × [\d.]+ mm\n$/);
    const { triangles } = readStl(new Uint8Array(readFileSync(out)));
    expect(edgeCounts(triangles).bad).toBe(0);
    const points = triangles.flatMap((t) => t.vertices);
    const side = (a: number) => Math.max(...points.map((v) => v[a]!)) - Math.min(...points.map((v) => v[a]!));
    expect(Math.max(side(0), side(1), side(2))).toBeCloseTo(60, 3);

    const glbOut = join(dir, 'quasi-60.glb');
    const g = runCli([
      'mesh',
      example3d('fig26-quasi-sphere'),
      '-o',
      glbOut,
      '-r',
      '12',
      '--print-size',
      '60',
    ]);
    expect(g.stdout).toMatch(/60\.0 × [\d.]+ mm \(in metres in the GLB/);
    const glb = new Uint8Array(readFileSync(glbOut));
    expect((await validateBytes(glb)).issues.numErrors).toBe(0);
    const position = (await new WebIO().readBinary(glb))
      .getRoot()
      .listMeshes()[0]!
      .listPrimitives()[0]!
      .getAttribute('POSITION')!;
    const [lo, hi] = [position.getMin([]), position.getMax([])];
    expect(Math.max(...hi.map((v, a) => v - lo[a]!))).toBeCloseTo(0.06, 6);
  });

  it('refuses a print size that is no length or out of range, before meshing', () => {
    const out = join(dir, 'bad-size.stl');
    for (const [size, message] of [
      ['0', /--print-size must be between 1 and 10000 mm, got 0/],
      ['20000', /--print-size must be between 1 and 10000 mm/],
      ['sixty', /--print-size expects the longest side in millimetres, such as 60, got "sixty"/],
      ['-60', /--print-size expects the longest side in millimetres/],
    ] as const) {
      const r = runCli(['mesh', example3d('fig26-quasi-sphere'), '-o', out, '--print-size', size]);
      expect(r.status).toBe(2);
      expect(r.stderr.split('\n')[0]).toMatch(message);
      expect(r.stderr).not.toMatch(/meshing/);
    }
    expect(existsSync(out)).toBe(false);
  });

  it('refuses an --out whose extension names no mesh format, before meshing', () => {
    const out = join(dir, 'model.obj');
    const r = runCli(['mesh', example3d('fig26-quasi-sphere'), '--out', out]);
    expect(r.status).toBe(2);
    expect(r.stderr).toMatch(/must end in \.stl, \.3mf or \.glb/);
    expect(existsSync(out)).toBe(false);
  });

  it('asks for --bounds on the infinite sphairahedron, and meshes a slab of it when given', () => {
    const out = join(dir, 'terrain.stl');
    const refused = runCli(['mesh', example3d('fig28-fractal-terrain'), '--out', out, '--resolution', '16']);
    expect(refused.status).toBe(1);
    expect(refused.stderr).toMatch(/unbounded.*--bounds|give bounds/);
    const r = runCli([
      'mesh',
      example3d('fig28-fractal-terrain'),
      '--out',
      out,
      '--resolution',
      '16',
      '--bounds',
      '-1,-1,-0.6,1,1,0.6',
    ]);
    expect(r.status).toBe(0);
    const { triangles } = readStl(new Uint8Array(readFileSync(out)));
    expect(edgeCounts(triangles).bad).toBe(0);
  });

  it('refuses a 2D graph, a bad resolution, bad bounds and a missing --out in one line each', () => {
    const flat = runCli([
      'mesh',
      join(ROOT, 'examples/apollonian-gasket.kleinflow.json'),
      '-o',
      join(dir, 'x.stl'),
    ]);
    expect(flat.status).toBe(1);
    expect(flat.stderr).toMatch(/not a 3D graph/);
    const res = runCli([
      'mesh',
      example3d('fig26-quasi-sphere'),
      '-o',
      join(dir, 'x.stl'),
      '--resolution',
      '2',
    ]);
    expect(res.status).not.toBe(0);
    expect(res.stderr).toMatch(/--resolution must be between/);
    const bounds = runCli([
      'mesh',
      example3d('fig26-quasi-sphere'),
      '-o',
      join(dir, 'x.stl'),
      '--bounds',
      '1,2,3',
    ]);
    expect(bounds.stderr).toMatch(/--bounds expects six numbers/);
    const noOut = runCli(['mesh', example3d('fig26-quasi-sphere')]);
    expect(noOut.stderr).toMatch(/missing --out/);
    for (const run of [flat, res, bounds, noOut]) expect(run.stderr).not.toMatch(/\n\s+at /);
  });

  it('refuses bounds whose extent overflows float64, and never writes an empty mesh with exit 0', () => {
    const out = join(dir, 'huge.stl');
    const quasiSphere = (...options: string[]) =>
      runCli(['mesh', example3d('fig26-quasi-sphere'), '-o', out, ...options]);
    const huge = quasiSphere('--bounds', '-1e308,-1e308,-1e308,1e308,1e308,1e308');
    expect(huge.status).toBe(2);
    expect(huge.stderr.split('\n')[0]).toMatch(/^kleinflow mesh: --bounds .*not finite in float64/);
    expect(existsSync(out)).toBe(false);
    // A box beside the solid: nothing to mesh is a failure, not an empty file.
    const away = quasiSphere('-r', '8', '--bounds', '50,50,50,51,51,51');
    expect(away.status).toBe(1);
    expect(away.stderr).toMatch(/no mesh: nothing solid/);
    expect(existsSync(out)).toBe(false);
  });
});
