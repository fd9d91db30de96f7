/** The element steps of shader-gen/elements against nodes/geometry (the math they must share). */
import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import type {
  InversionElement,
  MobiusElement,
  OuterInversionElement,
  ReflectionElement,
} from '../../nodes/core/scene.ts';
import type { Circle, Vec2 } from '../../nodes/core/values.ts';
import { invertPoint, reflectPoint } from '../../nodes/geometry/circle.ts';
import { twoCircleRegions } from '../../nodes/geometry/mobius.ts';
import { dist } from '../../nodes/geometry/vec.ts';
import type { IisState } from '../../shader-gen/elements/element-kind.ts';
import { ELEMENTS } from '../../shader-gen/elements/index.ts';
import { invertState } from '../../shader-gen/elements/inversion.ts';
import { reflectState } from '../../shader-gen/elements/reflection.ts';

const SEED = { seed: 42, numRuns: 200 } as const;
const coord = fc.double({ min: -4, max: 4, noNaN: true });
const point = fc.tuple(coord, coord) as fc.Arbitrary<Vec2>;
const circle = fc.record({
  c: point,
  r: fc.double({ min: 0.2, max: 3, noNaN: true }),
}) as fc.Arbitrary<Circle>;
const unit = fc
  .double({ min: 0, max: 2 * Math.PI, noNaN: true })
  .map((t): Vec2 => [Math.cos(t), Math.sin(t)]);
const state = (p: Vec2): IisState => ({ x: p[0], y: p[1], s: 1, depth: 0 });
const close = (a: Vec2, b: Vec2, tol = 1e-9) =>
  expect(dist(a, b)).toBeLessThan(tol * Math.max(1, Math.hypot(...b)));

describe('inversion element', () => {
  const kind = ELEMENTS.inversion.cpu;

  it('steps exactly the points inside, like invertPoint, with scale r²/|p−c|²', () => {
    fc.assert(
      fc.property(circle, point, (C, p) => {
        const e: InversionElement = { kind: 'inversion', nodeId: 'i', c: C.c, r: C.r };
        fc.pre(dist(p, C.c) > 1e-3);
        const st = state(p);
        const inside = dist(p, C.c) < C.r;
        expect(kind.inside(e, p[0], p[1])).toBe(inside);
        expect(kind.step(e, st)).toBe(inside);
        if (!inside) {
          expect(st).toEqual(state(p));
          return;
        }
        close([st.x, st.y], invertPoint(C, p)!);
        expect(st.depth).toBe(1);
        expect(st.s).toBeCloseTo(C.r ** 2 / dist(p, C.c) ** 2, 9);
        expect(kind.inside(e, st.x, st.y)).toBe(false); // lands outside
      }),
      SEED,
    );
  });

  it('is an involution, and the scales of the two steps multiply to 1', () => {
    fc.assert(
      fc.property(circle, point, (C, p) => {
        fc.pre(dist(p, C.c) > 1e-2);
        const st = state(p);
        invertState(st, C.c[0], C.c[1], C.r);
        invertState(st, C.c[0], C.c[1], C.r);
        close([st.x, st.y], p);
        expect(st.s).toBeCloseTo(1, 9);
      }),
      SEED,
    );
  });

  it('boundaryDistance is the distance to the circle', () => {
    const e: InversionElement = { kind: 'inversion', nodeId: 'i', c: [1, 0], r: 2 };
    expect(kind.boundaryDistance(e, 1, 0)).toBe(2);
    expect(kind.boundaryDistance(e, 4, 0)).toBe(1);
  });
});

describe('outer-inversion element (a circle mirror that keeps its inside)', () => {
  const kind = ELEMENTS['outer-inversion'].cpu;

  it('steps exactly the points outside, like invertPoint, and lands them inside', () => {
    fc.assert(
      fc.property(circle, point, (C, p) => {
        const e: OuterInversionElement = { kind: 'outer-inversion', nodeId: 'o', c: C.c, r: C.r };
        fc.pre(Math.abs(dist(p, C.c) - C.r) > 1e-9);
        const st = state(p);
        const outside = dist(p, C.c) > C.r;
        expect(kind.inside(e, p[0], p[1])).toBe(outside);
        expect(kind.step(e, st)).toBe(outside);
        if (!outside) {
          expect(st).toEqual(state(p));
          return;
        }
        close([st.x, st.y], invertPoint(C, p)!);
        expect(st.depth).toBe(1);
        expect(st.s).toBeCloseTo(C.r ** 2 / dist(p, C.c) ** 2, 9);
        expect(kind.inside(e, st.x, st.y)).toBe(false);
      }),
      SEED,
    );
  });

  it('lets NaN fall through and measures the distance to the circle', () => {
    const e: OuterInversionElement = { kind: 'outer-inversion', nodeId: 'o', c: [1, 0], r: 2 };
    expect(kind.step(e, state([Number.NaN, 0]))).toBe(false);
    expect(kind.boundaryDistance(e, 4, 0)).toBe(1);
  });
});

describe('reflection element', () => {
  const kind = ELEMENTS.reflection.cpu;

  it('steps exactly the points on the inside (right) side, like reflectPoint, scale 1', () => {
    fc.assert(
      fc.property(point, unit, point, (q, n, p) => {
        const e: ReflectionElement = { kind: 'reflection', nodeId: 'r', q, n };
        const h = (p[0] - q[0]) * n[0] + (p[1] - q[1]) * n[1];
        fc.pre(Math.abs(h) > 1e-9);
        const st = state(p);
        expect(kind.step(e, st)).toBe(h < 0);
        expect(kind.inside(e, p[0], p[1])).toBe(h < 0);
        expect(kind.boundaryDistance(e, p[0], p[1])).toBeCloseTo(Math.abs(h), 12);
        if (h >= 0) {
          expect(st).toEqual(state(p));
          return;
        }
        close([st.x, st.y], reflectPoint(q, n, p));
        expect(st).toMatchObject({ s: 1, depth: 1 });
        expect(kind.inside(e, st.x, st.y)).toBe(false);
      }),
      SEED,
    );
  });

  it('is an involution', () => {
    fc.assert(
      fc.property(point, unit, point, (q, n, p) => {
        const st = state(p);
        reflectState(st, q[0], q[1], n[0], n[1]);
        reflectState(st, q[0], q[1], n[0], n[1]);
        close([st.x, st.y], p, 1e-12 * 20);
        expect(st.s).toBe(1);
      }),
      SEED,
    );
  });
});

describe('two-circle Möbius element', () => {
  const kind = ELEMENTS.mobius.cpu;

  it('applies g = σ_C2∘σ_C1 in A and g⁻¹ = σ_C1∘σ_C2 in B, A tested first', () => {
    fc.assert(
      fc.property(circle, circle, point, (c1, c2, p) => {
        const R = twoCircleRegions(c1, c2);
        fc.pre(R.ok && dist(p, c1.c) > 1e-3 && dist(p, c2.c) > 1e-3);
        if (!R.ok) return;
        const e: MobiusElement = { kind: 'mobius', nodeId: 'm', c1, c2, a: R.a, b: R.b };
        const inR = (reg: typeof R.a) => (reg.outside ? dist(p, reg.c) > reg.r : dist(p, reg.c) < reg.r);
        const st = state(p);
        const stepped = kind.step(e, st);
        expect(stepped).toBe(inR(R.a) || inR(R.b));
        expect(kind.inside(e, p[0], p[1])).toBe(stepped);
        if (!stepped) return;
        const want = inR(R.a) ? invertPoint(c2, invertPoint(c1, p)!)! : invertPoint(c1, invertPoint(c2, p)!)!;
        close([st.x, st.y], want, 1e-7);
        expect(st.depth).toBe(1);
      }),
      SEED,
    );
  });

  it('g⁻¹ undoes g (the two branches are inverse maps)', () => {
    fc.assert(
      fc.property(circle, circle, point, (c1, c2, p) => {
        fc.pre(dist(p, c1.c) > 1e-2);
        const st = state(p);
        fc.pre(dist(invertPoint(c1, p)!, c2.c) > 1e-2);
        invertState(st, c1.c[0], c1.c[1], c1.r);
        invertState(st, c2.c[0], c2.c[1], c2.r);
        invertState(st, c2.c[0], c2.c[1], c2.r);
        invertState(st, c1.c[0], c1.c[1], c1.r);
        close([st.x, st.y], p, 1e-7);
        expect(st.s).toBeCloseTo(1, 6);
      }),
      SEED,
    );
  });
});
