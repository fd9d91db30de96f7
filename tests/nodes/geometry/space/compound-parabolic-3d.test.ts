import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import {
  applyCompoundParabolic3d,
  applyCompoundParabolic3dInverse,
  type CompoundParabolic3d,
  compoundParabolic3d,
  slabCoordinate,
} from '../../../../nodes/geometry/space/compound-parabolic-3d.ts';
import { iis3d } from '../../../../nodes/geometry/space/iis-3d.ts';
import { cross3, dist3, dot3, len3, sub3 } from '../../../../nodes/geometry/space/vec3.ts';
import { point3, real, SEED, unit3 } from './arbitraries.ts';

const setup = fc
  .record({ q: point3, n: unit3, h: real(0.2, 2), theta: real(-Math.PI, Math.PI) })
  .map(({ q, n, h, theta }) => {
    const g = compoundParabolic3d(q, n, h, theta);
    if (!g.ok) throw new Error(g.error);
    return g.value;
  });
/** Distance of x from the axis (q, n). */
const axisDistance = (g: CompoundParabolic3d, x: ReturnType<typeof sub3>) =>
  len3(cross3(sub3(x, g.point), g.normal));

describe('compound parabolic 3D (docs/math-3d.md §6)', () => {
  it('translates by 2h along the axis, rotates by the torsion about it, and keeps the distance to the axis', () => {
    fc.assert(
      fc.property(setup, point3, (g, x) => {
        const y = applyCompoundParabolic3d(g, x).x;
        expect(slabCoordinate(g, y) - slabCoordinate(g, x)).toBeCloseTo(2 * g.gap, 9);
        expect(axisDistance(g, y)).toBeCloseTo(axisDistance(g, x), 9);
        expect(dist3(applyCompoundParabolic3dInverse(g, y).x, x)).toBeLessThan(1e-9);
      }),
      SEED,
    );
  });

  it('maps A = {s < 0} onto {s < 2h} (missing B) and the rest onto B = {s > 2h}', () => {
    fc.assert(
      fc.property(setup, point3, (g, x) => {
        const s = slabCoordinate(g, x);
        const t = slabCoordinate(g, applyCompoundParabolic3d(g, x).x);
        if (s < 0) expect(t).toBeLessThan(2 * g.gap + 1e-9);
        else expect(t).toBeGreaterThan(2 * g.gap - 1e-9);
      }),
      SEED,
    );
  });

  it('zero torsion is the translation of Fig. 17; a quarter turn turns the offset from the axis by 90°', () => {
    const g = compoundParabolic3d([0, 0, 0], [0, 0, 2], 0.5, Math.PI / 2);
    expect(g.ok).toBe(true);
    if (!g.ok) return;
    const y = applyCompoundParabolic3d(g.value, [1, 0, -3]).x;
    expect(y[0]).toBeCloseTo(0, 12);
    expect(y[1]).toBeCloseTo(1, 12);
    expect(y[2]).toBeCloseTo(-2, 12);
    const plain = compoundParabolic3d([0, 0, 0], [0, 0, 1], 0.5, 0);
    if (plain.ok) expect(applyCompoundParabolic3d(plain.value, [1, 2, 3]).x).toEqual([1, 2, 4]);
    expect(compoundParabolic3d([0, 0, 0], [0, 0, 0], 1, 0).ok).toBe(false);
    expect(compoundParabolic3d([0, 0, 0], [0, 0, 1], 0, 0).ok).toBe(false);
  });

  it('the IIS folds any point into the slab 0 ≤ s ≤ 2h', () => {
    fc.assert(
      fc.property(setup, point3, (g, x) => {
        const r = iis3d([{ kind: 'compound-parabolic-3d', g }], x, 100);
        expect(r.escaped).toBe(true);
        const s = slabCoordinate(g, r.point);
        expect(s).toBeGreaterThanOrEqual(-1e-9);
        expect(s).toBeLessThanOrEqual(2 * g.gap + 1e-9);
        expect(dot3(g.normal, g.normal)).toBeCloseTo(1, 12);
      }),
      SEED,
    );
  });
});
