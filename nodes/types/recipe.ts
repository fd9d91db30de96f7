import { defineNode, type InputSpec } from '../core/define-node.ts';
import { diag } from '../core/diagnostics.ts';
import type { SceneElement } from '../core/scene-elements.ts';
import type { Circle } from '../core/values.ts';
import { type Complex, cabs, cnear } from '../geometry/complex.ts';
import { classifyMatrix, isAffine, type MobiusMatrix } from '../geometry/mobius-matrix.ts';
import {
  grandmaRecipe,
  jorgensenRecipe,
  maskitParameter,
  RECIPES,
  rileyRecipe,
} from '../geometry/recipes.ts';
import { maskitCirclesDisjoint } from './maskit.ts';
import { fmtComplex, matrixElement } from './mobius-matrix.ts';
import { fail } from './shared.ts';

const TRACES = { param: 'recipe', is: ['grandma', 'jorgensen'] } as const;
const RILEY = { param: 'recipe', is: ['riley'] } as const;
const part = (label: string, dflt: number, when: InputSpec['when']) =>
  ({ type: 'number', label, default: dflt, step: 0.01, when }) as const satisfies InputSpec;

/** "[[a, b], [c, d]]" with complex entries. */
const fmtMatrix = (m: MobiusMatrix) =>
  `[[${fmtComplex(m.a)}, ${fmtComplex(m.b)}], [${fmtComplex(m.c)}, ${fmtComplex(m.d)}]]`;

/**
 * A generator as an IIS element: the Ford rule on its isometric circles, or — for an affine
 * translation z ↦ z + t (c = 0, a = d = ±1) — the translation strip of width |t| centred on 0.
 * null for any other affine map (a similarity: no isometric circle, no strip).
 */
function generatorElement(m: MobiusMatrix, nodeId: string): SceneElement | null {
  if (!isAffine(m)) return matrixElement(m, nodeId);
  if (!cnear(m.a, m.d) || !cnear([m.a[0] * m.a[0] - m.a[1] * m.a[1], 2 * m.a[0] * m.a[1]], [1, 0]))
    return null;
  const t: Complex = [
    (m.b[0] * m.d[0] + m.b[1] * m.d[1]) / cabs(m.d) ** 2,
    (m.b[1] * m.d[0] - m.b[0] * m.d[1]) / cabs(m.d) ** 2,
  ];
  const period = cabs(t);
  if (!(period > 0)) return null;
  const n: Complex = [t[0] / period, t[1] / period];
  return { kind: 'translation', nodeId, q: [-t[0] / 2, -t[1] / 2], n, period };
}

/**
 * The isometric circles of the non-affine generators, with their images under a translation
 * generator's ±t (the strip folds them there too): the Ford rule is exact iff these are pairwise
 * disjoint or tangent.
 */
function isometric(elements: readonly SceneElement[]): Circle[] {
  const circles = elements.flatMap((e) =>
    e.kind === 'mobius-matrix' ? [e.forward, e.backward].map(({ c, r }) => ({ c, r })) : [],
  );
  const shifts = elements.flatMap((e) => (e.kind === 'translation' ? [e.n.map((x) => x * e.period)] : []));
  return circles.flatMap((c) => [
    c,
    ...shifts.flatMap(([tx, ty]) => [
      { c: [c.c[0] + tx, c.c[1] + ty] as const, r: c.r },
      { c: [c.c[0] - tx, c.c[1] - ty] as const, r: c.r },
    ]),
  ]);
}

/** Whether two of the circles overlap (cross or nest), beyond tangency. */
const someOverlap = (circles: readonly Circle[]) =>
  circles.some((c1, i) =>
    circles.some(
      (c2, j) => j > i && Math.hypot(c1.c[0] - c2.c[0], c1.c[1] - c2.c[1]) < (c1.r + c2.r) * (1 - 1e-9),
    ),
  );

export const recipeNode = defineNode({
  type: 'recipe',
  version: 1,
  label: 'Two-generator recipe',
  category: 'Generators',
  color: '#e85d75',
  doc: 'Generators a, b from a recipe of Indra’s Pearls — Grandma’s or Jørgensen’s (traces ta, tb, with abAB parabolic) or Riley’s (two parabolics) — as Möbius matrices; the node says what the IIS can draw of the group.',
  inputs: {
    ta_re: part('ta (real)', 2, TRACES),
    ta_im: part('ta (imag.)', 0, TRACES),
    tb_re: part('tb (real)', 2, TRACES),
    tb_im: part('tb (imag.)', 0, TRACES),
    c_re: part('c (real)', 0, RILEY),
    c_im: part('c (imag.)', 2, RILEY),
  },
  outputs: { elements: { type: 'element', label: 'elements' } },
  params: {
    recipe: {
      kind: 'enum',
      default: 'grandma',
      options: RECIPES,
      label: 'recipe',
      doc: 'Grandma’s and Jørgensen’s take the traces ta, tb; Riley’s the complex c of a = [[1, 0], [c, 1]], b = z + 2',
    },
  },
  evaluate: ({ inputs, params, nodeId }) => {
    const ta: Complex = [inputs.ta_re, inputs.ta_im];
    const tb: Complex = [inputs.tb_re, inputs.tb_im];
    const recipe = params.recipe;
    const group =
      recipe === 'riley'
        ? rileyRecipe([inputs.c_re, inputs.c_im])
        : recipe === 'grandma'
          ? grandmaRecipe(ta, tb)
          : jorgensenRecipe(ta, tb);
    if (!group) return fail(`the ${recipe} recipe divides by 0 for these traces; change ta or tb a little`);
    const readout = `a = ${fmtMatrix(group.a)}, b = ${fmtMatrix(group.b)}, tr ab = ${fmtComplex(group.tab)}`;
    const mu = maskitParameter(group);
    if (mu) {
      return {
        outputs: { elements: [{ kind: 'maskit', nodeId, mu }] },
        readout,
        diagnostics: [
          diag(
            'drawnInstead',
            {},
            `a and b are not both drawable by the IIS, but this group is a Maskit group (one parabolic generator, abAB parabolic): drawn is its limit set by Jos Leys's Maskit method, μ = ${fmtComplex(mu)}, in the Maskit group's own coordinates (conjugate to a, b by a Möbius map); ${maskitCirclesDisjoint(mu) ? 'exact here (its isometric circles are disjoint or tangent)' : 'approximate here: its isometric circles overlap (near the edge of the Maskit slice, or outside it)'}`,
          ),
        ],
      };
    }
    const elements = [generatorElement(group.a, nodeId), generatorElement(group.b, nodeId)];
    if (elements.some((e) => !e))
      return fail('a generator is an affine similarity: the IIS has no region for it');
    const types = [group.a, group.b].map((m) => classifyMatrix(m).type);
    const diagnostics = [];
    if (types.every((t) => t !== 'elliptic')) {
      const overlap = someOverlap(isometric(elements as SceneElement[]));
      // A warning where the picture is wrong; a note where the Ford rule happens to be exact.
      const drawn = overlap
        ? 'which overlap here, so the picture is not the group’s limit set'
        : 'which are disjoint or tangent here, so the picture is exact (a Ford domain)';
      diagnostics.push(
        diag(
          overlap ? 'notATiling' : 'drawnInstead',
          {},
          `a is ${types[0]} and b is ${types[1]}: with two such generators the IIS cannot draw every such group (no tile is known that every point reaches, paper §5.1.3). Drawn: the Ford rule on the isometric circles of a and b alone (a translation strip for z + 2), ${drawn}; with tb = 2 Grandma’s and Jørgensen’s groups are drawn exactly by the Maskit method`,
        ),
      );
    }
    return { outputs: { elements: elements as SceneElement[] }, readout, diagnostics };
  },
  overlay: (_ctx, out) =>
    out.elements.flatMap((e) =>
      e.kind === 'mobius-matrix'
        ? [
            { shape: 'circle' as const, circle: { c: e.forward.c, r: e.forward.r } },
            { shape: 'circle' as const, circle: { c: e.backward.c, r: e.backward.r } },
          ]
        : [],
    ),
});
