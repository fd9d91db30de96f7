/**
 * The 3D element nodes: sphere-inversion, plane-reflection, mobius-3d (with its classification
 * read-out), compound-loxodromic-3d (S3, S4 orthogonal to S1 and S2) and compound-parabolic-3d
 * (facing planes, translation by twice the gap, torsion).
 */
import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import type { NodeElement3d, Sphere, Vec3 } from '../../../nodes/core/scene-3d.ts';
import { stepElement3d } from '../../../nodes/geometry/space/iis-3d.ts';
import { dist3 } from '../../../nodes/geometry/space/vec3.ts';
import { evaluateGraph } from '../../../nodes/graph/evaluate.ts';
import { registry } from '../../../nodes/types/index.ts';
import { MOBIUS_3D_READOUT } from '../../../nodes/types/mobius-3d.ts';
import { nestedPair, point3, SEED } from '../geometry/space/arbitraries.ts';
import { doc, node } from '../support/doc.ts';

const alone = (type: string, params: Record<string, unknown> = {}) => {
  const result = evaluateGraph(doc([node('n', type, params)]), registry).nodes.get('n')!;
  return {
    ...result,
    element: (result.outputs?.element as NodeElement3d[] | undefined)?.[0],
    messages: result.diagnostics.map((d) => `${d.code} ${d.message}`),
  };
};

describe('sphere-inversion', () => {
  it('makes one sphere-inversion element carrying its node id', () => {
    const r = alone('sphere-inversion', { sphere: { center: [1, 0, 0], radius: 2 } });
    expect(r.element).toEqual({
      kind: 'sphere-inversion',
      nodeId: 'n',
      sphere: { center: [1, 0, 0], radius: 2 },
    });
  });

  it('refuses a sphere with radius ≤ 0', () => {
    expect(alone('sphere-inversion', { sphere: { center: [0, 0, 0], radius: 0 } }).messages).toEqual([
      "KF303 the sphere's radius must be positive, got 0",
    ]);
  });
});

describe('plane-reflection', () => {
  it('keeps the side its normal points to and reflects the other', () => {
    const e = alone('plane-reflection', { plane: { point: [0, 0, 1], normal: [0, 0, 2] } }).element!;
    expect(stepElement3d(e, [0, 0, 3])).toBeNull();
    expect(stepElement3d(e, [0, 0, 0])).toEqual({ x: [0, 0, 2], factor: 1 });
  });
});

describe('mobius-3d', () => {
  it.each([
    ['apart', [3, 0, 0], 1, 'hyperbolic'],
    ['nested', [0.3, 0, 0], 2, 'hyperbolic'],
    ['kissing', [2, 0, 0], 1, 'parabolic'],
    ['crossing', [1.2, 0, 0], 1, 'elliptic'],
  ] as const)('classifies spheres that are %s and shows it', (_what, c2, r2, type) => {
    const r = alone('mobius-3d', { s1: { center: [0, 0, 0], radius: 1 }, s2: { center: c2, radius: r2 } });
    expect(r.readout).toBe(MOBIUS_3D_READOUT[type]);
    expect(r.element?.kind).toBe('mobius-3d');
  });

  it('outputs S1′ = I_S2(S1)', () => {
    const r = alone('mobius-3d', {
      s1: { center: [0, 0, 0], radius: 1 },
      s2: { center: [3, 0, 0], radius: 1 },
    });
    // δ = 9 − 1 = 8, k = 1/8: centre 3 − 3/8, radius 1/8 (docs/math-3d.md §1).
    expect(r.outputs?.image).toEqual({ center: [3 - 3 / 8, 0, 0], radius: 1 / 8 });
  });

  it('refuses equal spheres and a sphere through the other’s centre', () => {
    const s = { center: [0, 0, 0], radius: 1 };
    expect(alone('mobius-3d', { s1: s, s2: s }).messages).toEqual([
      'KF303 S1 and S2 are the same sphere: the generator is the identity',
    ]);
    expect(alone('mobius-3d', { s1: { center: [1, 0, 0], radius: 1 }, s2: s }).messages[0]).toMatch(
      /S1 passes through the centre of S2/,
    );
    expect(alone('mobius-3d', { s2: { center: [0, 0, 0], radius: -2 } }).messages).toEqual([
      "KF303 S2's radius must be positive, got -2",
    ]);
  });
});

describe('compound-loxodromic-3d', () => {
  const orthogonal = (a: Sphere, b: Sphere) =>
    dist3(a.center, b.center) ** 2 - (a.radius ** 2 + b.radius ** 2);

  it('builds S3 and S4 orthogonal to S1 and S2 from the control points (property)', () => {
    fc.assert(
      fc.property(nestedPair, point3, point3, point3, ({ s1, s2 }, p, q1, q2) => {
        const r = alone('compound-loxodromic-3d', { s1, s2, p, q1, q2 });
        if (!r.outputs) {
          expect(r.messages[0]).toMatch(/^KF303 (S3|S4): /);
          return;
        }
        const s3 = r.outputs.s3 as Sphere;
        const s4 = r.outputs.s4 as Sphere;
        if (s3.radius > 100 || s4.radius > 100) return; // nearly planar: the test's tolerance is relative
        for (const s of [s3, s4])
          for (const base of [s1, s2])
            expect(Math.abs(orthogonal(s, base))).toBeLessThan(1e-6 * (1 + s.radius ** 2));
        expect(r.element?.kind).toBe('compound-loxodromic-3d');
      }),
      SEED,
    );
  });

  it('evaluates with its defaults, and names S3 when P, P′, P″, Q1 are coplanar', () => {
    expect(alone('compound-loxodromic-3d').element?.kind).toBe('compound-loxodromic-3d');
    // Q1 in the plane z = 0 of the centres and P: S3 does not exist.
    const r = alone('compound-loxodromic-3d', { q1: [0.2, 0.7, 0] });
    expect(r.messages[0]).toMatch(/^KF303 S3: Sphere\(P, P′, P″, Q\): the four points are coplanar/);
  });
});

describe('compound-parabolic-3d', () => {
  const facing = (torsion: number) => ({
    p1: { point: [0, 0, -1], normal: [0, 0, 1] },
    p2: { point: [0, 0, 1], normal: [0, 0, -1] },
    torsion,
  });

  it('translates by twice the gap along P1’s normal, turning by the torsion', () => {
    const r = alone('compound-parabolic-3d', facing(90));
    expect(r.readout).toBe('translation 4, turn 90°');
    const moved = stepElement3d(r.element!, [1, 0, -2])!;
    // x + 2h·n = (1, 0, 2), then turned 90° about the z axis through (0, 0, −1).
    const want: Vec3 = [0, 1, 2];
    moved.x.forEach((v, i) => {
      expect(v).toBeCloseTo(want[i]!, 12);
    });
    expect(stepElement3d(r.element!, [1, 0, 0])).toBeNull(); // in the slab
  });

  it('refuses planes that are not parallel, or do not face each other', () => {
    const p = facing(0);
    expect(
      alone('compound-parabolic-3d', { ...p, p2: { point: [0, 0, 1], normal: [0, 1, -1] } }).messages[0],
    ).toMatch(/must be parallel with normals facing each other/);
    expect(
      alone('compound-parabolic-3d', { ...p, p2: { point: [0, 0, -3], normal: [0, 0, -1] } }).messages[0],
    ).toMatch(/P2 must lie on the side P1’s normal points to/);
  });
});
