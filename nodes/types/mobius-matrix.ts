import { defineNode, type InputSpec } from '../core/define-node.ts';
import { diag } from '../core/diagnostics.ts';
import type { MobiusMatrixElement } from '../core/scene-elements.ts';
import { type Complex, cabs } from '../geometry/complex.ts';
import {
  classifyMatrix,
  isAffine,
  isometricCircles,
  type MatrixClass,
  type MobiusMatrix,
  normalizeMatrix,
} from '../geometry/mobius-matrix.ts';
import { degrees, fail, fmt } from './shared.ts';

/** "1.2 − 0.5i", "3", "2i". */
export function fmtComplex(z: Complex): string {
  const [re, im] = [fmt(z[0]), fmt(Math.abs(z[1]))];
  if (fmt(z[1]) === '0') return re;
  const imag = `${im === '1' ? '' : im}i`;
  if (re === '0') return z[1] < 0 ? `−${imag}` : imag;
  return `${re} ${z[1] < 0 ? '−' : '+'} ${imag}`;
}

/** What the node shows: the type, the trace and what one step does. */
export function describeMatrix(cls: MatrixClass): string {
  const head = `${cls.type}, trace ${fmtComplex(cls.trace)}`;
  if (cls.rotation !== undefined) return `${head}: rotation ${degrees(cls.rotation)}`;
  if (cls.multiplier) {
    const k = cls.multiplier;
    const turn = Math.atan2(k[1], k[0]);
    return `${head}: scale ×${fmt(cabs(k))}${cls.type === 'loxodromic' ? `, turn ${degrees(turn)}` : ''}`;
  }
  return head;
}

/** The Ford-rule element of a det-1 matrix with c ≠ 0: g inside I(g), g⁻¹ inside I(g⁻¹). */
export function matrixElement(m: MobiusMatrix, nodeId: string): MobiusMatrixElement {
  const { forward, backward } = isometricCircles(m);
  return {
    kind: 'mobius-matrix',
    nodeId,
    ...m,
    forward: { ...forward, outside: false },
    backward: { ...backward, outside: false },
  };
}

const part = (label: string, dflt: number) =>
  ({ type: 'number', label, default: dflt, step: 0.01 }) as const satisfies InputSpec;

export const mobiusMatrixNode = defineNode({
  type: 'mobius-matrix',
  version: 1,
  label: 'Möbius (matrix)',
  category: 'Generators',
  color: '#e85d75',
  doc: 'The Möbius map g(z) = (az + b)/(cz + d) and its inverse, acting on their isometric circles (a Ford domain); normalised to ad − bc = 1.',
  inputs: {
    a_re: part('a (real)', 1.25),
    a_im: part('a (imag.)', 0),
    b_re: part('b (real)', 0.75),
    b_im: part('b (imag.)', 0),
    c_re: part('c (real)', 0.75),
    c_im: part('c (imag.)', 0),
    d_re: part('d (real)', 1.25),
    d_im: part('d (imag.)', 0),
  },
  outputs: {
    element: { type: 'element', label: 'element' },
    isometric: { type: 'circle', label: 'I(g)', doc: 'the isometric circle of g: inside it, g applies' },
    isometricInverse: {
      type: 'circle',
      label: 'I(g⁻¹)',
      doc: 'the isometric circle of g⁻¹: inside it, g⁻¹ applies',
    },
  },
  params: {},
  evaluate: ({ inputs, nodeId }) => {
    const z = (k: 'a' | 'b' | 'c' | 'd'): Complex => [inputs[`${k}_re`], inputs[`${k}_im`]];
    const m = normalizeMatrix({ a: z('a'), b: z('b'), c: z('c'), d: z('d') });
    if (!m) return fail('ad − bc = 0: the matrix is not invertible (the map would be constant)');
    if (isAffine(m)) {
      return fail(
        'c = 0: the map is affine (z ↦ (az + b)/d) and has no isometric circles; use the Translation strip or Spiral similarity node',
      );
    }
    const cls = classifyMatrix(m);
    const element = matrixElement(m, nodeId);
    const { forward, backward } = element;
    // I(g) and I(g⁻¹) are disjoint or tangent iff |τ| ≥ 2 (their centres are |τ|/|c| apart). At
    // τ = 0 they coincide and g is an involution (g = g⁻¹): the outside is a fundamental domain.
    const t = cabs(cls.trace);
    const overlap = t < 2 * (1 - 1e-9) && t > 1e-9;
    return {
      outputs: {
        element: [element],
        isometric: { c: forward.c, r: forward.r },
        isometricInverse: { c: backward.c, r: backward.r },
      },
      readout: describeMatrix(cls),
      diagnostics: overlap
        ? [
            diag(
              'notATiling',
              {},
              'the isometric circles overlap (|a + d| < 2): the region outside them is not a fundamental domain, the images overlap',
            ),
          ]
        : [],
    };
  },
  overlay: (_ctx, out) => [
    { shape: 'circle', circle: out.isometric },
    { shape: 'circle', circle: out.isometricInverse },
  ],
});
