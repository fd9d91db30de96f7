import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import {
  applyMobius3d,
  applyMobius3dInverse,
  classifyTwoSpheres,
  type Mobius3d,
  mobius3d,
  stepMobius3d,
} from '../../../../nodes/geometry/space/mobius-3d.ts';
import type { Sphere } from '../../../../nodes/geometry/space/sphere.ts';
import { dist3 } from '../../../../nodes/geometry/space/vec3.ts';
import { disjointPair, nestedPair, real, SEED, unit3 } from './arbitraries.ts';
import { around, checkPingPong, depthIn } from './ping-pong.ts';

const build = (s1: Sphere, s2: Sphere): Mobius3d => {
  const g = mobius3d(s1, s2);
  if (!g.ok) throw new Error(g.error);
  return g.value;
};

describe('classifyTwoSpheres', () => {
  const s1: Sphere = { center: [0, 0, 0], radius: 1 };
  it('apart or nested → hyperbolic, kissing → parabolic, crossing → elliptic', () => {
    expect(classifyTwoSpheres(s1, { center: [3, 0, 0], radius: 1 })).toBe('hyperbolic');
    expect(classifyTwoSpheres(s1, { center: [0.1, 0, 0], radius: 3 })).toBe('hyperbolic');
    expect(classifyTwoSpheres(s1, { center: [0, 2, 0], radius: 1 })).toBe('parabolic');
    expect(classifyTwoSpheres(s1, { center: [0, 0, 1], radius: 2 })).toBe('parabolic');
    expect(classifyTwoSpheres(s1, { center: [1, 0, 0], radius: 1 })).toBe('elliptic');
  });
});

describe('mobius3d regions (docs/math-3d.md §2)', () => {
  it('nested: inside S1 → G, outside S1′ → G⁻¹; disjoint: inside S1 → G, inside S1′ → G⁻¹', () => {
    const nested = build({ center: [0, 0, 0], radius: 1 }, { center: [0.3, 0, 0], radius: 2 });
    expect([nested.a.inside, nested.b.inside]).toEqual([true, false]);
    const apart = build({ center: [0, 0, 0], radius: 1 }, { center: [3, 0, 0], radius: 1 });
    expect([apart.a.inside, apart.b.inside]).toEqual([true, true]);
    const flipped = build({ center: [0, 0, 0], radius: 3 }, { center: [0.5, 0, 0], radius: 1 });
    expect([flipped.a.inside, flipped.b.inside]).toEqual([false, true]);
  });

  it('rejects S1 = S2 and S1 through the centre of S2 with a message', () => {
    expect(mobius3d({ center: [1, 1, 1], radius: 1 }, { center: [1, 1, 1], radius: 1 })).toEqual({
      ok: false,
      error: expect.stringMatching(/identity/),
    });
    expect(mobius3d({ center: [0, 0, 0], radius: 1 }, { center: [1, 0, 0], radius: 1 }).ok).toBe(false);
  });
});

describe('mobius3d ping-pong (G(A) ∩ B = ∅, G(outside A) = B)', () => {
  for (const [name, pairs] of [
    ['nested', nestedPair],
    ['disjoint', disjointPair],
  ] as const) {
    it(`holds for ${name} spheres, and steps apply G in A and G⁻¹ in B`, () => {
      fc.assert(
        fc.property(pairs, unit3, real(0, 3), unit3, real(0, 3), ({ s1, s2 }, u, t, v, w) => {
          const g = build(s1, s2);
          checkPingPong(
            g,
            (x) => applyMobius3d(g, x),
            (x) => applyMobius3dInverse(g, x),
            around(s1, u, t),
          );
          const y = around(g.s1Image, v, w);
          const step = stepMobius3d(g, y);
          if (depthIn(g.a, y) > 1e-9) expect(step).toEqual(applyMobius3d(g, y));
          else if (depthIn(g.b, y) > 1e-9) {
            expect(step).toEqual(applyMobius3dInverse(g, y));
            expect(depthIn(g.a, step!.x)).toBeLessThan(1e-7); // G⁻¹(B) misses A
          } else if (depthIn(g.a, y) < -1e-9 && depthIn(g.b, y) < -1e-9) expect(step).toBeNull();
        }),
        SEED,
      );
    });
  }

  it('maps S1 onto S1′', () => {
    fc.assert(
      fc.property(fc.oneof(nestedPair, disjointPair), unit3, ({ s1, s2 }, u) => {
        const g = build(s1, s2);
        const y = applyMobius3d(g, around(s1, u, 1))!;
        expect(dist3(y.x, g.s1Image.center) / g.s1Image.radius).toBeCloseTo(1, 8);
      }),
      SEED,
    );
  });
});
