import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import type { MobiusMatrixElement } from '../../../nodes/core/scene.ts';
import type { Vec2 } from '../../../nodes/core/values.ts';
import { type Complex, cabs } from '../../../nodes/geometry/complex.ts';
import {
  applyMatrix,
  inverseMatrix,
  isometricCircles,
  type MobiusMatrix,
  normalizeMatrix,
} from '../../../nodes/geometry/mobius-matrix.ts';
import { dist } from '../../../nodes/geometry/vec.ts';
import type { IisState } from '../../../shader-gen/elements/element-kind.ts';
import { elementRecord } from '../../../shader-gen/elements/index.ts';

const SEED = { seed: 42, numRuns: 300 } as const;
const part = fc.double({ min: -2, max: 2, noNaN: true });
const cplx = fc.tuple(part, part) as fc.Arbitrary<Complex>;
const rawMatrix = fc.record({ a: cplx, b: cplx, c: cplx, d: cplx });

const element = (m: MobiusMatrix): MobiusMatrixElement => {
  const { forward, backward } = isometricCircles(m);
  return {
    kind: 'mobius-matrix',
    nodeId: 'n',
    ...m,
    forward: { ...forward, outside: false },
    backward: { ...backward, outside: false },
  };
};

/** |g'(z)| by a central difference |g(z + h) − g(z − h)| / 2h, h small against the distance to the pole. */
function numericScale(m: MobiusMatrix, z: Vec2): number {
  const pole = isometricCircles(m).forward.c;
  const h = 1e-5 * dist(z, pole);
  return dist(applyMatrix(m, [z[0] + h, z[1]])!, applyMatrix(m, [z[0] - h, z[1]])!) / (2 * h);
}

describe('mobius-matrix element', () => {
  it('inside I(g) it applies g with scale |g′| = 1/|cz + d|²; inside I(g⁻¹) (only) it applies g⁻¹', () => {
    fc.assert(
      fc.property(
        rawMatrix,
        fc.double({ min: 0.05, max: 0.99, noNaN: true }),
        fc.double({ min: 0, max: 6.3, noNaN: true }),
        (raw, u, t) => {
          const m = normalizeMatrix(raw);
          fc.pre(m !== null && cabs(m.c) > 0.05 && cabs(m.c) < 20);
          const e = element(m!);
          const kind = elementRecord(e).cpu;
          for (const [disk, map] of [
            [e.forward, m!],
            [e.backward, inverseMatrix(m!)],
          ] as const) {
            const z: Vec2 = [disk.c[0] + u * disk.r * Math.cos(t), disk.c[1] + u * disk.r * Math.sin(t)];
            const inForward = dist(z, e.forward.c) < e.forward.r;
            const expectedMap = inForward ? m! : map; // I(g) is tested first
            const st: IisState = { x: z[0], y: z[1], s: 1, depth: 0 };
            expect(kind.step(e, st)).toBe(true);
            const image = applyMatrix(expectedMap, z)!;
            expect(dist([st.x, st.y], image)).toBeLessThan(1e-9 * Math.max(1, Math.hypot(...image)));
            expect(st.depth).toBe(1);
            expect(st.s / numericScale(expectedMap, z)).toBeCloseTo(1, 4);
          }
        },
      ),
      SEED,
    );
  });

  it('outside both isometric circles nothing happens', () => {
    const m = normalizeMatrix({ a: [1.25, 0], b: [0.75, 0], c: [0.75, 0], d: [1.25, 0] })!;
    const e = element(m);
    const st: IisState = { x: 0, y: 0, s: 1, depth: 0 };
    expect(elementRecord(e).cpu.inside(e, 0, 0)).toBe(false);
    expect(elementRecord(e).cpu.step(e, st)).toBe(false);
    expect(st).toEqual({ x: 0, y: 0, s: 1, depth: 0 });
    expect(elementRecord(e).cpu.boundaryDistance(e, 0, 0)).toBeCloseTo(5 / 3 - 4 / 3, 12);
  });
});
