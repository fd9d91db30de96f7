import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import type { CompoundLoxodromic3d } from '../../../../nodes/geometry/space/compound-loxodromic-3d.ts';
import {
  applyCompoundLoxodromic3d,
  applyCompoundLoxodromic3dInverse,
  compoundLoxodromic3d,
} from '../../../../nodes/geometry/space/compound-loxodromic-3d.ts';
import { invertChain } from '../../../../nodes/geometry/space/mobius-3d.ts';
import { dist3, type Vec3 } from '../../../../nodes/geometry/space/vec3.ts';
import { compoundSetup, real, SEED, unit3 } from './arbitraries.ts';
import { around, checkPingPong, depthIn } from './ping-pong.ts';

const H = (g: CompoundLoxodromic3d, x: Vec3) => invertChain([g.base.s1, g.base.s2], x);
const R = (g: CompoundLoxodromic3d, x: Vec3) => invertChain([g.s3, g.s4], x);

describe('compound loxodromic 3D (docs/math-3d.md §3)', () => {
  it('the rotation R = I_S4∘I_S3 commutes with H = I_S2∘I_S1 and keeps each side of S1 and S1′', () => {
    fc.assert(
      fc.property(compoundSetup, unit3, real(0, 3), (g, u, t) => {
        const x = around(g.base.s1, u, t);
        const hr = H(g, R(g, x)!.x)!;
        const rh = R(g, H(g, x)!.x)!;
        expect(dist3(hr.x, rh.x)).toBeLessThan(1e-6 * Math.max(1, dist3(hr.x, [0, 0, 0])));
        const rx = R(g, x)!.x;
        for (const side of [g.base.a, g.base.b]) {
          if (Math.abs(depthIn(side, x)) > 1e-6) expect(depthIn(side, rx) > 0).toBe(depthIn(side, x) > 0);
        }
      }),
      SEED,
    );
  });

  it('G = (I_S4∘I_S3)∘(I_S2∘I_S1) maps A onto the complement of B: G(A) misses B, G(outside A) = B', () => {
    fc.assert(
      fc.property(compoundSetup, unit3, real(0, 3), (g, u, t) => {
        checkPingPong(
          g.base,
          (x) => applyCompoundLoxodromic3d(g, x),
          (x) => applyCompoundLoxodromic3dInverse(g, x),
          around(g.base.s1, u, t),
        );
      }),
      SEED,
    );
  });

  it('G⁻¹ maps B into the complement of A', () => {
    fc.assert(
      fc.property(compoundSetup, unit3, real(1.01, 3), (g, u, t) => {
        const y = around(g.base.s1Image, u, t); // outside S1′ = B in the nested set-up
        expect(depthIn(g.base.b, y)).toBeGreaterThan(0);
        expect(depthIn(g.base.a, applyCompoundLoxodromic3dInverse(g, y)!.x)).toBeLessThan(1e-7);
      }),
      SEED,
    );
  });

  it('the printed order (I_S4∘I_S3)∘(I_S1∘I_S2) keeps A inside A: the IIS could never reach the tile', () => {
    fc.assert(
      fc.property(compoundSetup, unit3, real(0, 0.99), (g, u, t) => {
        const x = around(g.base.s1, u, t);
        const printed = invertChain([g.base.s2, g.base.s1, g.s3, g.s4], x)!;
        expect(depthIn(g.base.a, printed.x)).toBeGreaterThan(0);
      }),
      SEED,
    );
  });

  it('reports which sphere could not be built', () => {
    const s1 = { center: [0, 0, 0] as Vec3, radius: 1 };
    const s2 = { center: [0.2, 0, 0] as Vec3, radius: 3 };
    const res = compoundLoxodromic3d(s1, s2, [0.5, 0.3, 0], [1, 1, 0], [0, 0, 1]);
    expect(res).toEqual({ ok: false, error: expect.stringMatching(/^S3: .*coplanar/) });
  });
});
