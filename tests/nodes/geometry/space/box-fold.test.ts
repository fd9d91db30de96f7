/**
 * The box fold (docs/math-3d.md §10): it lands in the closed box, equals the artists' fold
 * u ← 2·clamp(u, −h, h) − u repeated, is an isometry for the map chosen at a point, fixes the box,
 * and never moves a point farther from any point of the box (the lemma behind its end cover).
 */
import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import {
  applyBoxFold,
  type BoxFold,
  boxFoldRegionDistance,
  outsideBox,
  stepBoxFold,
} from '../../../../nodes/geometry/space/box-fold.ts';
import { dist3, type Vec3 } from '../../../../nodes/geometry/space/vec3.ts';
import { point3, real, SEED } from './arbitraries.ts';

const box = fc
  .record({ center: point3, halfSize: fc.tuple(real(0.2, 2), real(0.2, 2), real(0.2, 2)) })
  .map((b) => b as BoxFold);
/** Anywhere up to ten box sizes away. */
const far = fc.tuple(real(-20, 20), real(-20, 20), real(-20, 20)) as fc.Arbitrary<Vec3>;
/** A point of the closed box, by fractions of its half sizes. */
const inBox = (b: BoxFold, f: Vec3): Vec3 =>
  b.center.map((c, k) => c + f[k]! * b.halfSize[k]!) as unknown as Vec3;
const fractions = fc.tuple(real(-1, 1), real(-1, 1), real(-1, 1)) as fc.Arbitrary<Vec3>;

/** The artists' fold, one clamp-reflection per pass, repeated until the point is in the box. */
function clampFoldRepeated(b: BoxFold, x: Vec3): { x: Vec3; passes: number } {
  let p = x;
  let passes = 0;
  while (outsideBox(b, p) && passes < 1000) {
    p = p.map((v, k) => {
      const c = b.center[k]!;
      const h = b.halfSize[k]!;
      return c + 2 * Math.min(h, Math.max(-h, v - c)) - (v - c);
    }) as unknown as Vec3;
    passes++;
  }
  return { x: p, passes };
}

describe('box fold (docs/math-3d.md §10)', () => {
  it('lands in the closed box, where the repeated clamp fold lands', () => {
    fc.assert(
      fc.property(box, far, (b, x) => {
        const step = stepBoxFold(b, x);
        if (!outsideBox(b, x)) return expect(step).toBeNull();
        expect(step!.factor).toBe(1);
        step!.x.forEach((v, k) => {
          expect(Math.abs(v - b.center[k]!)).toBeLessThanOrEqual(b.halfSize[k]! + 1e-9);
        });
        const repeated = clampFoldRepeated(b, x);
        expect(repeated.passes).toBeGreaterThan(0);
        expect(dist3(step!.x, repeated.x)).toBeLessThan(1e-9);
      }),
      SEED,
    );
  });

  it('is an isometry (the map chosen at a point moves every point rigidly) and fixes the box', () => {
    fc.assert(
      fc.property(box, far, far, point3, fractions, (b, at, y, z, f) => {
        const d = dist3(applyBoxFold(b, at, y), applyBoxFold(b, at, z));
        expect(d).toBeCloseTo(dist3(y, z), 9);
        const p = inBox(b, f);
        expect(stepBoxFold(b, p)).toBeNull();
        expect(boxFoldRegionDistance(b, p)).toBeGreaterThanOrEqual(0);
      }),
      SEED,
    );
  });

  it('never moves a point farther from a point of the box: |fold(z) − p| ≤ |z − p|', () => {
    fc.assert(
      fc.property(box, far, fractions, (b, z, f) => {
        const p = inBox(b, f);
        const folded = stepBoxFold(b, z)?.x ?? z;
        expect(dist3(folded, p)).toBeLessThanOrEqual(dist3(z, p) * (1 + 1e-12) + 1e-12);
      }),
      SEED,
    );
  });

  it('measures the distance to its region (0 outside) by the nearest face', () => {
    const b: BoxFold = { center: [1, 0, 0], halfSize: [1, 2, 3] };
    expect(boxFoldRegionDistance(b, [1.5, 0, 0])).toBeCloseTo(0.5, 12);
    expect(boxFoldRegionDistance(b, [1, 1.8, 0])).toBeCloseTo(0.2, 12);
    expect(boxFoldRegionDistance(b, [3, 0, 0])).toBe(0);
    // x = 2.5: reflected in the face x = 2 → 1.5.
    expect(stepBoxFold(b, [2.5, 0, 0])!.x).toEqual([1.5, 0, 0]);
    // y = 9: 9 − 8 (one period) = 1 — a translation by two reflections.
    expect(stepBoxFold(b, [1, 9, 0])!.x).toEqual([1, 1, 0]);
  });
});
