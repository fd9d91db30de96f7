import { join } from 'node:path';
import { describe, expect, it } from 'vitest';
import { iis3d } from '../../nodes/geometry/space/iis-3d.ts';
import { invertInSphere } from '../../nodes/geometry/space/sphere.ts';
import { cliTempDir, evaluateFile, ROOT, runCli, writeIn } from './run-cli.ts';

const FIG11 = join(ROOT, 'examples/3d/fig11-sphere-inversion-fractal.kleinflow.json');
const CUBE = join(ROOT, 'examples/3d/fig24-orbit-of-a-cube.kleinflow.json');
const PLANE = join(ROOT, 'examples/hyperbolic-237.kleinflow.json');

const dir = cliTempDir('kleinflow-sample3d-');
const file = (name: string, content: string) => writeIn(dir, name, content);
type Row = { depth: number; x: number; y: number; z: number; escaped: boolean; distance: number | null };
const sample = (graph: string, points: unknown) => {
  const r = runCli(['sample', graph, '--points', file('pts.json', JSON.stringify(points))]);
  return { ...r, rows: r.status === 0 ? (JSON.parse(r.stdout) as { points: Row[] }).points : [] };
};

describe('kleinflow sample, 3D graph', () => {
  it('prints depth, final x, y, z, escaped and distance, matching the IIS in space', () => {
    const pts: [number, number, number][] = [
      [0, 0, 0],
      [0.9, 0, 0],
      [0.75, 0.1, 0.05],
      [2, 2, 2],
    ];
    const r = sample(FIG11, pts);
    expect(r.stderr).toBe('');
    expect(r.status).toBe(0);
    const scene = evaluateFile(FIG11).scene3d!;
    r.rows.forEach((row, i) => {
      expect(Object.keys(row)).toEqual(['depth', 'x', 'y', 'z', 'escaped', 'distance']);
      const want = iis3d(scene.elements, pts[i]!, scene.maxIterations);
      expect(row).toMatchObject({ depth: want.depth, x: want.point[0], y: want.point[1], z: want.point[2] });
      expect(row.escaped).toBe(want.escaped);
    });
    // The seed (centre 0, radius 0.29): its centre is 0.29 inside; (2, 2, 2) is |(2,2,2)| − 0.29 away.
    expect(r.rows[0]!.distance).toBeCloseTo(-0.29, 12);
    expect(r.rows[3]!.distance).toBeCloseTo(Math.sqrt(12) - 0.29, 12);
    // (0.9, 0, 0) lies in the mirror at (1, 0, 0), r = 0.7: one inversion, factor 0.49 / 0.01 = 49.
    expect(r.rows[1]).toMatchObject({ depth: 1, escaped: true });
    expect(r.rows[1]!.distance).toBeCloseTo((3.9 - 0.29) / 49, 12);
  });

  it('is zero on the image of the seed: a point of I_S(seed) has distance ≈ 0', () => {
    // The seed's point (0.29, 0, 0) inverted in the mirror at (1, 0, 0), r = 0.7.
    const onImage = invertInSphere({ center: [1, 0, 0], radius: 0.7 }, [0.29, 0, 0])!.x;
    const r = sample(FIG11, [onImage]);
    expect(r.rows[0]!.depth).toBe(1);
    expect(Math.abs(r.rows[0]!.distance!)).toBeLessThan(1e-12);
  });

  it('uses the box’s signed distance for a box seed', () => {
    const r = sample(CUBE, [
      [0, 0, 0],
      [0, 0.35, 0.3],
    ]);
    expect(r.status).toBe(0);
    expect(r.rows[0]!.distance).toBeCloseTo(-0.2, 12); // the cube's half size
    expect(r.rows[1]!.depth).toBe(0);
    expect(r.rows[1]!.distance).toBeCloseTo(Math.hypot(0.15, 0.1), 12); // to the edge y = z = 0.2 (outside every mirror)
  });

  it('prints null distances for a graph without seeds', () => {
    const g = JSON.stringify({
      format: 'kleinflow',
      version: 1,
      meta: {},
      nodes: [
        { id: 'm', type: 'sphere-inversion', position: [0, 0], params: {} },
        { id: 'r', type: 'render-3d', position: [300, 0], params: {} },
      ],
      edges: [{ id: 'e', from: { node: 'm', port: 'element' }, to: { node: 'r', port: 'elements' } }],
      view: { center: [0, 0], scale: 4 },
    });
    const r = sample(file('no-seeds.json', g), [[0.5, 0, 0]]);
    expect(r.status).toBe(0);
    expect(r.rows[0]).toEqual({ depth: 1, x: 2, y: 0, z: 0, escaped: true, distance: null });
  });

  it.each([
    [
      FIG11,
      [[0, 0]],
      /\[0\]: expected \[x, y, z\] with three finite numbers, got an array of 2 \(a point of the plane: this graph is 3D/,
    ],
    [
      PLANE,
      [[0, 0, 0]],
      /\[0\]: expected \[x, y\] with two finite numbers, got an array of 3 \(a point of space: this graph is 2D/,
    ],
  ])('refuses points of the wrong dimension in one line (%s)', (graph, points, message) => {
    const r = sample(graph, points);
    expect(r.status).toBe(1);
    expect(r.stdout).toBe('');
    expect(r.stderr.trim().split('\n')).toHaveLength(1);
    expect(r.stderr).toMatch(message);
  });

  it('a 2D-only command refuses a 3D graph in one line instead of saying it has no render node', () => {
    const r = runCli(['svg', FIG11, '--out', join(dir, 'x.svg')]);
    expect(r.status).toBe(1);
    expect(r.stderr.trim().split('\n')).toHaveLength(1);
    expect(r.stderr).toMatch(
      /is a 3D graph \(its render node is Render 3D\): this command works on 2D graphs/,
    );
  });

  it('--trace is refused on a 3D graph in one line (usage), not ignored', () => {
    const r = runCli(['sample', FIG11, '--trace', '--points', file('pts.json', '[[0,0,0]]')]);
    expect(r.status).toBe(2);
    expect(r.stderr).toMatch(/--trace works on 2D graphs/);
  });
});
