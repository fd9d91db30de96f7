import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import type { Vec2 } from '../../../nodes/core/values.ts';
import {
  type AntiMobius,
  applyMap,
  compose,
  IDENTITY,
  imageCircle,
  inverse,
  inversionMap,
  matrixMap,
  reflectionMap,
} from '../../../nodes/geometry/anti-mobius.ts';
import { invertPoint, reflectPoint } from '../../../nodes/geometry/circle.ts';
import { cabs, cmul, csub } from '../../../nodes/geometry/complex.ts';

const SEED = { seed: 42, numRuns: 200 } as const;
const coord = fc.double({ min: -3, max: 3, noNaN: true });
const point = fc.tuple(coord, coord) as fc.Arbitrary<Vec2>;
const radius = fc.double({ min: 0.2, max: 2, noNaN: true });
const angle = fc.double({ min: 0, max: 2 * Math.PI, noNaN: true });

/** A random map: an inversion, a reflection or a Möbius matrix (det ≠ 0). */
const anyMap: fc.Arbitrary<AntiMobius> = fc.oneof(
  fc.tuple(point, radius).map(([c, r]) => inversionMap({ c, r })),
  fc.tuple(point, angle).map(([q, t]) => reflectionMap(q, [Math.cos(t), Math.sin(t)])),
  fc
    .tuple(point, point, point)
    .map(([a, b, c]) => ({ a, b, c, d: [1 + a[1], c[0] - 0.5] as Vec2 }))
    .filter((m) => cabs(csub(cmul(m.a, m.d), cmul(m.b, m.c))) > 0.1)
    .map(matrixMap),
);

const close = (p: Vec2 | null, q: Vec2 | null, tol = 1e-7) => {
  expect(p).not.toBeNull();
  expect(q).not.toBeNull();
  if (!p || !q) return;
  expect(Math.hypot(p[0] - q[0], p[1] - q[1])).toBeLessThan(tol * (1 + Math.hypot(q[0], q[1])));
};

describe('anti-Möbius maps', () => {
  it('inversion and reflection agree with the point formulas', () => {
    fc.assert(
      fc.property(point, radius, point, angle, (c, r, p, t) => {
        fc.pre(Math.hypot(p[0] - c[0], p[1] - c[1]) > 0.1);
        close(applyMap(inversionMap({ c, r }), p), invertPoint({ c, r }, p));
        const n: Vec2 = [Math.cos(t), Math.sin(t)];
        close(applyMap(reflectionMap(c, n), p), reflectPoint(c, n, p));
      }),
      SEED,
    );
  });

  it('compose applies the right map first, inverse undoes', () => {
    fc.assert(
      fc.property(anyMap, anyMap, point, (f, g, p) => {
        const gp = applyMap(g, p);
        fc.pre(gp !== null && Math.hypot(gp[0], gp[1]) < 1e3);
        const fgp = applyMap(f, gp);
        fc.pre(fgp !== null && Math.hypot(fgp[0], fgp[1]) < 1e3);
        close(applyMap(compose(f, g), p), fgp, 1e-6);
        const fp = applyMap(f, p);
        fc.pre(fp !== null && Math.hypot(fp[0], fp[1]) < 1e3);
        close(applyMap(inverse(f), fp), p, 1e-6);
        expect(compose(f, g).anti).toBe(f.anti !== g.anti);
      }),
      SEED,
    );
  });

  it('an inversion is its own inverse and an involution', () => {
    const f = inversionMap({ c: [0.3, -0.2], r: 0.7 });
    close(applyMap(compose(f, f), [1.1, 0.4]), [1.1, 0.4]);
    close(applyMap(IDENTITY, [2, 3]), [2, 3]);
  });

  it('imageCircle carries every point of a circle onto the image circle', () => {
    fc.assert(
      fc.property(anyMap, point, radius, angle, (f, c, r, t) => {
        const k = imageCircle(f, { c, r });
        fc.pre(k !== null && k.r < 1e3);
        if (!k) return;
        const p = applyMap(f, [c[0] + r * Math.cos(t), c[1] + r * Math.sin(t)]);
        fc.pre(p !== null);
        if (!p) return;
        expect(Math.abs(Math.hypot(p[0] - k.c[0], p[1] - k.c[1]) - k.r)).toBeLessThan(1e-6 * (1 + k.r));
      }),
      SEED,
    );
  });
});
