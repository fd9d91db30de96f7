/**
 * A four-dimensional Kleinian group (paper Fig. 6): two Möbius transformations of space as 2×2
 * quaternion matrices in Sp^K(1,1), x ↦ (a x + b)(c x + d)⁻¹ (docs/math-3d.md "Quaternion Kleinian
 * groups"). Either Sakugawa's family (three numbers) or two matrices typed in. Its limit set is
 * found by depth-first search at the Render 3D node's camera and drawn there as shaded dots.
 */
import { defineNode } from '../core/define-node.ts';
import { diag } from '../core/diagnostics.ts';
import type { LimitSet3d } from '../core/limit-set-3d.ts';
import type { Quaternion } from '../geometry/space/quaternion.ts';
import {
  type QMatrix,
  sakugawaGenerators,
  spNormalised,
  spProblem,
} from '../geometry/space/quaternion-mobius.ts';
import { fail, fmt } from './shared.ts';

/** Sakugawa's default A, B written out: the "matrices" field starts from the family's picture. */
const DEFAULT_MATRICES = (() => {
  const q = (v: Quaternion) => v.map((x) => String(Number(x.toFixed(10)))).join(' ');
  return sakugawaGenerators(-2, 0.3, 0.3)
    .map((m, i) => `${i === 0 ? 'A' : 'B'}: ${[m.a, m.b, m.c, m.d].map(q).join(', ')}`)
    .join('; ');
})();

/** The 32 numbers of "A: a, b, c, d; B: a, b, c, d" (each quaternion w x y z), or why not. */
export function parseQuaternionMatrices(text: string): readonly [QMatrix, QMatrix] | string {
  const nums = (text.replace(/[AB]\s*:/g, ' ').match(/[-+]?(?:\d+\.?\d*|\.\d+)(?:e[-+]?\d+)?/gi) ?? []).map(
    Number,
  );
  if (nums.length !== 32)
    return `"matrices" needs 32 numbers (A then B; each of a, b, c, d as w x y z), it has ${nums.length}`;
  const quat = (at: number): Quaternion => [nums[at]!, nums[at + 1]!, nums[at + 2]!, nums[at + 3]!];
  const matrix = (at: number): QMatrix => ({
    a: quat(at),
    b: quat(at + 4),
    c: quat(at + 8),
    d: quat(at + 12),
  });
  return [matrix(0), matrix(16)];
}

/** Relative tolerance of the Sp^K(1,1) conditions for typed-in matrices. */
const TYPED_TOLERANCE = 1e-4;

export const quaternionGroupNode = defineNode({
  type: 'quaternion-group',
  version: 1,
  label: 'Quaternion Kleinian group',
  category: '3D',
  color: '#ff8a65',
  doc: 'A four-dimensional Kleinian group (Fig. 6): generators A, B as 2×2 quaternion matrices acting on space by x ↦ (ax + b)(cx + d)⁻¹; wire it into Render 3D, which draws its limit set (depth-first search) as shaded dots.',
  inputs: {
    x: {
      type: 'number',
      label: 'x',
      default: -2,
      step: 0.01,
      doc: 'Sakugawa family: the real part of z, between −4 and 0',
      when: { param: 'family', is: ['sakugawa'] },
    },
    thetaA: {
      type: 'number',
      label: 'θ_A (rad)',
      default: 0.3,
      step: 0.01,
      doc: 'Sakugawa family: A’s twist q_A = cos θ_A + k sin θ_A',
      when: { param: 'family', is: ['sakugawa'] },
    },
    thetaB: {
      type: 'number',
      label: 'θ_B (rad)',
      default: 0.3,
      step: 0.01,
      doc: 'Sakugawa family: B’s twist q_B = cos θ_B + k sin θ_B (B turns by 2θ_B about the x axis)',
      when: { param: 'family', is: ['sakugawa'] },
    },
    leafPx: {
      type: 'number',
      label: 'leaf size (px)',
      default: 1.2,
      step: 0.1,
      doc: 'a word ends when its points are this close on screen: smaller is finer and slower',
    },
    dotPx: {
      type: 'number',
      label: 'dot size (px)',
      default: 1,
      step: 0.1,
      doc: 'dot radius at the camera’s target distance',
    },
    maxDepth: {
      type: 'number',
      label: 'max depth',
      default: 300,
      doc: 'the longest word, 1…2000 (words near a parabolic fixed point shrink only like 1/n)',
      more: true,
    },
    maxWords: {
      type: 'number',
      label: 'max words',
      default: 1_000_000,
      doc: 'the most words one search visits, 1…5 000 000',
      more: true,
    },
    colorA: { type: 'color', label: 'colour a', default: '#f2664d' },
    colorB: { type: 'color', label: 'colour b', default: '#4d99f2' },
    colorAi: { type: 'color', label: 'colour A⁻¹', default: '#ffcc4d' },
    colorBi: { type: 'color', label: 'colour B⁻¹', default: '#66cc73' },
  },
  outputs: { group: { type: 'limit3', label: 'group' } },
  params: {
    family: {
      kind: 'enum',
      default: 'sakugawa',
      options: ['sakugawa', 'matrices'],
      label: 'generators',
      doc: 'sakugawa: A = [[q_A, 0], [z q_A, q_A]], B = [[q_B, q_B], [0, q_B]] with z = x + √(−x(x+4))·|sin(θ_A+θ_B)| j; matrices: type A and B',
    },
    matrices: {
      kind: 'string',
      default: DEFAULT_MATRICES,
      maxLength: 2000,
      label: 'matrices',
      doc: '"A: a, b, c, d; B: a, b, c, d", each entry a quaternion w x y z (w + xi + yj + zk); points of space are x + yi + zj',
      when: { param: 'family', is: ['matrices'] },
    },
  },
  evaluate: ({ inputs: i, params, nodeId }) => {
    let generators: readonly [QMatrix, QMatrix];
    if (params.family === 'matrices') {
      const parsed = parseQuaternionMatrices(params.matrices);
      if (typeof parsed === 'string') return fail(parsed);
      generators = parsed;
    } else {
      if (!(i.x > -4 && i.x < 0)) return fail(`x = ${fmt(i.x)} is outside the family’s range −4 < x < 0`);
      generators = sakugawaGenerators(i.x, i.thetaA, i.thetaB);
    }
    const names = ['A', 'B'];
    for (const [n, g] of generators.entries()) {
      // Typed-in numbers are rounded: conditions hold to 1e-4 of the entries' size.
      const problem = spProblem(g, TYPED_TOLERANCE);
      if (problem)
        return {
          diagnostics: [
            problem.kind === 'singular'
              ? diag('quaternionSingular', { port: 'matrices' }, names[n]!, problem.detail)
              : diag('quaternionNotSp', { port: 'matrices' }, names[n]!, problem.detail),
          ],
        };
    }
    const group: LimitSet3d = {
      nodeId,
      generators: [spNormalised(generators[0]), spNormalised(generators[1])],
      leafPx: Math.min(50, Math.max(0.3, i.leafPx)),
      dotPx: Math.min(50, Math.max(0.1, i.dotPx)),
      maxDepth: Math.round(Math.min(2000, Math.max(1, i.maxDepth))),
      maxWords: Math.round(Math.min(5_000_000, Math.max(1, i.maxWords))),
      colors: [i.colorA, i.colorB, i.colorAi, i.colorBi],
    };
    return {
      outputs: { group },
      readout: params.family === 'matrices' ? 'A, B typed in' : `z₀ = ${fmt(i.x)}`,
    };
  },
});
