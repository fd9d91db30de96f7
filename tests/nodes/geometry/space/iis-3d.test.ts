import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import { applyCompoundLoxodromic3dInverse } from '../../../../nodes/geometry/space/compound-loxodromic-3d.ts';
import { type Element3d, iis3d } from '../../../../nodes/geometry/space/iis-3d.ts';
import { dist3, type Vec3 } from '../../../../nodes/geometry/space/vec3.ts';
import { compoundSetup, real, SEED, unit3 } from './arbitraries.ts';
import { around, depthIn } from './ping-pong.ts';

describe('iis3d', () => {
  it('a point inside one inversion sphere is inverted once, with factor r²/|x−c|²', () => {
    const e: Element3d = { kind: 'sphere-inversion', sphere: { center: [0, 0, 0], radius: 2 } };
    expect(iis3d([e], [0.5, 0, 0], 10)).toEqual({ depth: 1, point: [8, 0, 0], factor: 16, escaped: true });
    expect(iis3d([e], [3, 0, 0], 10)).toEqual({ depth: 0, point: [3, 0, 0], factor: 1, escaped: true });
  });

  it('two facing plane mirrors translate the point into the slab between them', () => {
    const planes: Element3d[] = [
      { kind: 'plane-reflection', plane: { point: [0, 0, 0], normal: [0, 0, 1] } },
      { kind: 'plane-reflection', plane: { point: [0, 0, 1], normal: [0, 0, -1] } },
    ];
    const r = iis3d(planes, [0.2, 0.3, 4.25], 50);
    expect(r.escaped).toBe(true);
    expect(r.point[2]).toBeCloseTo(0.25, 12); // 4.25 → −2.25 → 2.25 → −0.25 → 0.25
    expect(r.factor).toBe(1);
  });

  it('reports escaped = false when the budget runs out', () => {
    const planes: Element3d[] = [
      { kind: 'plane-reflection', plane: { point: [0, 0, 0], normal: [0, 0, 1] } },
      { kind: 'plane-reflection', plane: { point: [0, 0, 1], normal: [0, 0, -1] } },
    ];
    expect(iis3d(planes, [0, 0, 40.5], 3).escaped).toBe(false);
  });

  it('undoes k applications of G⁻¹ from a tile point of a compound loxodromic: depth k, the same point, factor inverse', () => {
    fc.assert(
      fc.property(compoundSetup, unit3, real(1.01, 1.5), fc.integer({ min: 1, max: 4 }), (g, u, t, k) => {
        const y = around(g.base.s1, u, t);
        fc.pre(depthIn(g.base.b, y) < -1e-3); // in the tile: outside S1, inside S1′
        let x: Vec3 = y;
        let f = 1;
        for (let i = 0; i < k; i++) {
          const m = applyCompoundLoxodromic3dInverse(g, x)!;
          x = m.x;
          f *= m.factor;
        }
        const r = iis3d([{ kind: 'compound-loxodromic-3d', g }], x, 50);
        expect(r.depth).toBe(k);
        expect(r.escaped).toBe(true);
        expect(dist3(r.point, y)).toBeLessThan(1e-6);
        expect(r.factor * f).toBeCloseTo(1, 6);
      }),
      SEED,
    );
  });
});
