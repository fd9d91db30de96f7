/**
 * The Maskit element (docs/math.md "The Maskit slice"): every step is a group element of
 * ⟨a, b⟩ (a(z) = μ + 1/z, b(z) = z + 2) that magnifies, the picture is periodic under b and
 * symmetric under the half-turn z ↦ μ − z, its boundary distance is a true lower bound, and at the
 * cusp μ = 2i the disk |z − 1 − i| < 1 is a component of the regular set.
 */
import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import type { MaskitElement } from '../../../nodes/core/scene.ts';
import type { Complex } from '../../../nodes/geometry/complex.ts';
import { applyMatrix, composeMatrices, type MobiusMatrix } from '../../../nodes/geometry/mobius-matrix.ts';
import type { IisState } from '../../../shader-gen/elements/element-kind.ts';
import { maskit } from '../../../shader-gen/elements/maskit.ts';
import { interpret, prepare } from '../../../shader-gen/interpret.ts';
import { pathMargin } from '../../../shader-gen/path-margin.ts';

const SEED = { seed: 41, numRuns: 400 } as const;
const element = (u: number, v: number): MaskitElement => ({ kind: 'maskit', nodeId: 'm', mu: [u, v] });
const muArb = fc
  .tuple(fc.double({ min: -1, max: 1, noNaN: true }), fc.double({ min: 1.6, max: 2.6, noNaN: true }))
  .map(([u, v]) => element(u, v));
const pointIn = (e: MaskitElement) =>
  fc.tuple(
    fc.double({ min: -3, max: 3, noNaN: true }),
    fc.double({ min: -0.5, max: e.mu[1] + 0.5, noNaN: true }),
  );

const A = (mu: Complex): MobiusMatrix => ({ a: [mu[1], -mu[0]], b: [0, -1], c: [0, -1], d: [0, 0] });
const aInverse = (mu: Complex): MobiusMatrix => ({ a: [0, 0], b: [0, 1], c: [0, 1], d: [-mu[1], mu[0]] });
const shift = (k: number): MobiusMatrix => ({ a: [1, 0], b: [2 * k, 0], c: [0, 0], d: [1, 0] });

describe('Maskit element, CPU', () => {
  it('a step is a∘b^−k or a⁻¹∘b^−m applied as a matrix: the same point, a factor > 1', () => {
    fc.assert(
      fc.property(
        muArb.chain((e) => fc.tuple(fc.constant(e), pointIn(e))),
        ([e, [x, y]]) => {
          const st: IisState = { x, y, s: 1, depth: 0 };
          const applied = maskit.cpu.step(e, st);
          expect(applied).toBe(maskit.cpu.inside(e, x, y));
          if (!applied) {
            expect(st).toEqual({ x, y, s: 1, depth: 0 });
            return;
          }
          expect(st.depth).toBe(1);
          expect(st.s).toBeGreaterThan(1);
          // One of the two families, with the nearest translate.
          const k = Math.floor(x / 2 + 0.5);
          const m = Math.floor((x - e.mu[0]) / 2 + 0.5);
          // Within 10⁻¹⁵ of a centre the element clamps (Q_MIN) instead of sending z towards ∞.
          if (Math.min(Math.hypot(x - 2 * k, y), Math.hypot(x - e.mu[0] - 2 * m, y - e.mu[1])) < 1e-12)
            return;
          const candidates = [
            composeMatrices(A(e.mu), shift(-k)),
            composeMatrices(aInverse(e.mu), shift(-m)),
          ].map((g) => applyMatrix(g, [x, y]) as Complex);
          const hit = candidates.some(
            (w) => Math.hypot(w[0] - st.x, w[1] - st.y) <= 1e-9 * Math.max(1, Math.hypot(...w)),
          );
          expect(hit).toBe(true);
        },
      ),
      SEED,
    );
  });

  it('boundaryDistance is a lower bound: moving less than it never changes whether a step applies', () => {
    fc.assert(
      fc.property(
        muArb.chain((e) => fc.tuple(fc.constant(e), pointIn(e))),
        fc.double({ min: 0, max: 2 * Math.PI, noNaN: true }),
        fc.double({ min: 0, max: 0.99, noNaN: true }),
        ([e, [x, y]], turn, frac) => {
          const d = maskit.cpu.boundaryDistance(e, x, y);
          const r = d * frac;
          expect(maskit.cpu.inside(e, x + r * Math.cos(turn), y + r * Math.sin(turn))).toBe(
            maskit.cpu.inside(e, x, y),
          );
        },
      ),
      SEED,
    );
  });

  it('the picture is periodic under b (z + 2) and symmetric under the half-turn z ↦ μ − z', () => {
    fc.assert(
      fc.property(
        muArb.chain((e) => fc.tuple(fc.constant(e), pointIn(e))),
        ([e, [x, y]]) => {
          const scene = { elements: [e], maxIterations: 60 };
          const prepared = prepare([e]);
          const pts: Complex[] = [
            [x, y],
            [x + 2, y],
            [e.mu[0] - x, e.mu[1] - y],
          ];
          // Runs that pass within rounding of a boundary may branch differently: skip them.
          if (pts.some((p) => pathMargin(prepared, 60, p).margin < 1e-9)) return;
          const runs = pts.map((p) => interpret(scene, p));
          for (const r of runs.slice(1)) {
            expect(r.escaped).toBe(runs[0].escaped);
            if (runs[0].escaped) expect(r.depth).toBe(runs[0].depth);
          }
        },
      ),
      SEED,
    );
  });

  it('at the cusp μ = 2i the disk |z − 1 − i| < 1 is regular: its points reach the tile inside it', () => {
    const e = element(0, 2);
    fc.assert(
      fc.property(
        fc.double({ min: 0, max: 0.97, noNaN: true }),
        fc.double({ min: 0, max: 2 * Math.PI, noNaN: true }),
        (r, t) => {
          const p: Complex = [1 + r * Math.cos(t), 1 + r * Math.sin(t)];
          const run = interpret({ elements: [e], maxIterations: 400 }, p);
          expect(run.escaped).toBe(true);
          // The disk is a component of the regular set: its orbit stays in the images of the disk,
          // never in the half-planes the group keeps (the strip's outside).
          expect(run.final[1]).toBeGreaterThan(0);
          expect(run.final[1]).toBeLessThan(2);
        },
      ),
      { seed: 3, numRuns: 200 },
    );
  });
});
