/** The render-3d node's placement warnings: camera inside a mirror or a seed, seeds outside the domain. */
import { describe, expect, it } from 'vitest';
import type { NodeElement3d, Seed3d } from '../../../nodes/core/scene-3d.ts';
import { mobius3d } from '../../../nodes/geometry/space/mobius-3d.ts';
import {
  cameraDiagnostics,
  gpuRangeDiagnostics3d,
  seedDiagnostics,
} from '../../../nodes/types/space-checks.ts';

const mirror: NodeElement3d = {
  kind: 'sphere-inversion',
  nodeId: 'm',
  sphere: { center: [0, 0, 0], radius: 1 },
};
const floor: NodeElement3d = {
  kind: 'plane-reflection',
  nodeId: 'f',
  plane: { point: [0, 0, 0], normal: [0, 0, 1] },
};
const box: Seed3d = { kind: 'box', nodeId: 'b', center: [5, 0, 0], halfSize: [1, 1, 1], color: [1, 1, 1] };
const ball = (x: number, r: number): Seed3d => ({
  kind: 'sphere',
  nodeId: 's',
  sphere: { center: [x, 0, 0], radius: r },
  color: [1, 1, 1],
});
const codes = (ds: readonly { code: string; message: string }[]) => ds.map((d) => `${d.code} ${d.message}`);

describe('cameraDiagnostics', () => {
  it('warns inside an inversion sphere and inside a seed, naming them', () => {
    expect(codes(cameraDiagnostics([0.5, 0, 0], [mirror], []))[0]).toMatch(
      /^KF316 the camera is inside the region of element "m": the IIS turns that region inside out/,
    );
    expect(codes(cameraDiagnostics([5.5, 0.5, 0], [], [box]))).toEqual([
      'KF316 the camera is inside seed "b": it sees only the inside of that seed',
    ]);
  });

  it('warns with the camera exactly at an inversion centre (where inverting is undefined)', () => {
    expect(codes(cameraDiagnostics([0, 0, 0], [mirror], []))[0]).toMatch(
      /^KF316 the camera is inside the region of element "m"/,
    );
  });

  it('says nothing outside, or below a plane mirror (an isometry draws the same picture)', () => {
    expect(cameraDiagnostics([3, 0, 0], [mirror], [box])).toEqual([]);
    expect(cameraDiagnostics([3, 0, -2], [floor], [])).toEqual([]);
  });
});

describe('seedDiagnostics', () => {
  it('flags a seed ball that reaches into an inversion sphere, even when its centre and axis points are outside', () => {
    // Centre at distance 1.3 along (1, 1, 0)/√2, radius 0.35: the ball reaches to 0.95 < 1 on the diagonal.
    const c = 1.3 / Math.SQRT2;
    const seed: Seed3d = {
      kind: 'sphere',
      nodeId: 's',
      sphere: { center: [c, c, 0], radius: 0.35 },
      color: [1, 1, 1],
    };
    expect(codes(seedDiagnostics([seed], [mirror]))).toEqual([
      'KF314 seed "s" is not in the fundamental domain: the region of element "m" holds part of it, so its images overlap (move the seed out of that region)',
    ]);
    expect(seedDiagnostics([ball(1.4, 0.35)], [mirror])).toEqual([]);
  });

  it('names a generator whose region holds the seed, and a plane whose moved side does', () => {
    const g = mobius3d({ center: [0, 0, 0], radius: 1 }, { center: [3, 0, 0], radius: 1 });
    if (!g.ok) throw new Error(g.error);
    const lox: NodeElement3d = { kind: 'mobius-3d', nodeId: 'g', g: g.value };
    expect(seedDiagnostics([ball(0.2, 0.1)], [lox])[0]?.message).toMatch(/region of element "g"/);
    expect(seedDiagnostics([ball(1.5, 0.1)], [lox])).toEqual([]);
    expect(seedDiagnostics([{ ...box, center: [5, 0, 0.5] }], [floor])[0]?.message).toMatch(
      /region of element "f"/,
    );
  });
});

describe('gpuRangeDiagnostics3d', () => {
  it('KF405 for a seed or element value the float32 shader overflows on when squaring, naming its node', () => {
    const far = ball(1e308, 1);
    expect(gpuRangeDiagnostics3d([mirror], [far])).toEqual([
      expect.objectContaining({ code: 'KF405', severity: 'warning', port: 'seeds' }),
    ]);
    expect(gpuRangeDiagnostics3d([mirror], [far])[0].message).toMatch(
      /a value of 1e\+308 is beyond .*, so seed "s" does not draw/,
    );
    const huge: NodeElement3d = { ...mirror, sphere: { center: [0, 0, 0], radius: 1e20 } };
    expect(gpuRangeDiagnostics3d([huge], [])).toMatchObject([
      { code: 'KF405', port: 'elements', message: expect.stringContaining('element "m"') },
    ]);
  });

  it('says nothing for ordinary values', () => {
    expect(gpuRangeDiagnostics3d([mirror, floor], [box, ball(3, 1)])).toEqual([]);
  });
});
