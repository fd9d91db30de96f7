/**
 * The box-fold element record (shader-gen/space/elements/box-fold.ts, docs/math-3d.md §10): its CPU
 * step is the geometry's fold, moves a tracked pole by the same isometry (so |x − pole| is kept),
 * counts one application, and its end cover is 0 outside the box and ∞ in it, while the region
 * distance (used at mirror images) is the true one. Its GLSL twin is checked by the 3D parity test
 * (the Fig. 38 example and the pseudo-Kleinian fixture).
 */
import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import type { Element3d } from '../../../nodes/core/scene-3d.ts';
import { boxFoldRegionDistance, stepBoxFold } from '../../../nodes/geometry/space/box-fold.ts';
import type { Vec3 } from '../../../nodes/geometry/space/vec3.ts';
import { boxFold } from '../../../shader-gen/space/elements/box-fold.ts';
import type { Walk3dState } from '../../../shader-gen/space/elements/element-3d-kind.ts';
import { point3, real, SEED } from '../../nodes/geometry/space/arbitraries.ts';

type BoxFoldElement = Extract<Element3d, { kind: 'box-fold' }>;

const element = fc
  .record({ center: point3, halfSize: fc.tuple(real(0.2, 2), real(0.2, 2), real(0.2, 2)) })
  .map((box) => ({ kind: 'box-fold', box }) as BoxFoldElement);
const far = fc.tuple(real(-20, 20), real(-20, 20), real(-20, 20)) as fc.Arbitrary<Vec3>;

describe('box-fold element record', () => {
  it('steps as the geometry folds, moving the pole rigidly with the point', () => {
    fc.assert(
      fc.property(element, far, point3, (e, x, pole) => {
        const st: Walk3dState = {
          x: x[0],
          y: x[1],
          z: x[2],
          s: 1,
          depth: 0,
          pole: { x: pole[0], y: pole[1], z: pole[2] },
        };
        const before = Math.hypot(x[0] - pole[0], x[1] - pole[1], x[2] - pole[2]);
        const applied = boxFold.cpu.step(e, st);
        const expected = stepBoxFold(e.box, x);
        expect(applied).toBe(expected !== null);
        expect(st.depth).toBe(applied ? 1 : 0);
        expect(st.s).toBe(1);
        const at = expected?.x ?? x;
        expect([st.x, st.y, st.z].map((v, k) => v - at[k]!).every((d) => Math.abs(d) < 1e-9)).toBe(true);
        const p = st.pole!;
        expect(Math.hypot(st.x - p.x, st.y - p.y, st.z - p.z)).toBeCloseTo(before, 8);
      }),
      SEED,
    );
  });

  it('has no cover at the end of a walk in the box, and the true region distance elsewhere', () => {
    fc.assert(
      fc.property(element, far, (e, x) => {
        const region = boxFold.cpu.regionDistance(e, ...x);
        expect(region).toBeCloseTo(boxFoldRegionDistance(e.box, x), 12);
        const end = boxFold.cpu.endCover!(e, ...x);
        expect(end).toBe(stepBoxFold(e.box, x) ? 0 : Number.POSITIVE_INFINITY);
      }),
      SEED,
    );
  });

  it('packs centre and half sizes into two rows', () => {
    const e: BoxFoldElement = { kind: 'box-fold', box: { center: [1, 2, 3], halfSize: [0.5, 1, 2] } };
    expect(boxFold.glsl.pack(e)).toEqual([1, 2, 3, 0, 0.5, 1, 2, 0]);
    expect(boxFold.glsl.pack(e)).toHaveLength(4 * boxFold.glsl.vec4s);
    expect(boxFold.glsl.step({ pole: true, applied: '' })).toContain(
      'pole = d0.xyz + sg * (pole - d0.xyz) + tau;',
    );
  });
});
