/**
 * Seed solid: a 3D orbit seed written as a formula of x, y, z (relative to its centre) and a, b, c,
 * negative inside, kept within a bounding ball (docs/formula.md "3D seed shapes"). The tracer
 * needs a distance bound: a formula that is a true distance (a torus, a capsule, a rounded box) is
 * used as it is; one whose sampled slope exceeds 1 is divided by more than that, with a warning
 * (KF330), so the picture stays safe where the sample saw the formula (nodes/formula/solid.ts).
 */
import { defineNode } from '../core/define-node.ts';
import { diag } from '../core/diagnostics.ts';
import type { Seed3d } from '../core/scene-3d.ts';
import { formulaFor } from '../formula/checked.ts';
import { SOLID_NAMES } from '../formula/names.ts';
import { MAX_FORMULA_LENGTH } from '../formula/parse.ts';
import { type SlopeCheck, sampledSlope } from '../formula/solid.ts';
import { MATERIAL_PARAM, REFLECTIVITY_INPUT, withMaterial } from './seed-material.ts';
import { fail, fmt } from './shared.ts';
import { fmt3, point3Input, radiusTo, sphereHandles, sphereProblem } from './space-shared.ts';

/** The default: a torus of radii a (round the z axis) and b: |(|(x, y)| − a, z)| − b, a true distance. */
export const TORUS = 'length(point(length(point(x, y)) - a, z)) - b';

/** Divide a measured slope S > 1 by this much more: the sample may have missed steeper places. */
export const SLOPE_MARGIN = 1.25;

/** The last slope check per node: a drag re-evaluates the graph every frame with the same values. */
const checks = new Map<string, { readonly key: string; readonly check: SlopeCheck }>();

export const seedSolidNode = defineNode({
  type: 'seed-solid',
  version: 1,
  label: 'Seed solid',
  category: '3D',
  color: '#ba68c8',
  doc:
    'A 3D orbit seed written as a formula of x, y, z (from its centre) and a, b, c, negative inside ' +
    '(a torus by default), kept within a ball; the 3D render draws it and all its images. Best when ' +
    'the formula is a distance (slope ≤ 1); a steeper one is checked and divided, with a warning.',
  inputs: {
    center: point3Input('centre', 0, 0, 0),
    radius: { type: 'number', label: 'bounding radius', default: 0.5, step: 0.01 },
    a: { type: 'number', label: 'a', default: 0.32, step: 0.01 },
    b: { type: 'number', label: 'b', default: 0.1, step: 0.01 },
    c: { type: 'number', label: 'c', default: 0, step: 0.01 },
    color: { type: 'color', label: 'colour', default: '#ffb454' },
    reflectivity: REFLECTIVITY_INPUT,
  },
  outputs: { seed: { type: 'seed3', label: 'seed' } },
  params: {
    material: MATERIAL_PARAM,
    formula: {
      kind: 'string',
      default: TORUS,
      maxLength: MAX_FORMULA_LENGTH,
      label: 'inside where < 0',
      doc: 'a formula of x, y, z (from the centre), a, b, c giving a number: the solid is where it is negative',
    },
  },
  evaluate: ({ nodeId, inputs, params }) => {
    const text = params.formula;
    const problem = sphereProblem({ center: inputs.center, radius: inputs.radius }, 'the bounding ball');
    if (problem) return fail(problem);
    const checked = formulaFor(
      nodeId,
      text,
      SOLID_NAMES,
      ['number'],
      "a seed solid's formula gives a number (negative inside)",
    );
    if ('problem' in checked) return { diagnostics: [checked.problem] };
    const numbers = [inputs.a, inputs.b, inputs.c] as const;
    const key = `${text}\n${numbers.join(',')},${inputs.radius}`;
    let check = checks.get(nodeId);
    if (check?.key !== key) {
      check = { key, check: sampledSlope(checked.formula.run, numbers, inputs.radius) };
      checks.set(nodeId, check);
    }
    const { slope, inside, undefinedAt } = check.check;
    if (!inside)
      return fail(
        'the formula is nowhere negative at the points sampled in the bounding ball (a 10 × 10 × 10 grid): the solid is empty, or much smaller than its ball (make the bounding radius fit it)',
      );
    const divisor = slope > 1.001 ? slope * SLOPE_MARGIN : 1;
    const plain: Seed3d = {
      kind: 'formula',
      nodeId,
      center: inputs.center,
      radius: inputs.radius,
      formula: text,
      numbers,
      slope: divisor,
      color: inputs.color,
    };
    const { seed, diagnostics: material } = withMaterial(plain, params.material, inputs.reflectivity);
    const diagnostics = [
      ...material,
      ...(divisor > 1 ? [diag('formulaSlope', { nodeId }, fmt(slope), fmt(divisor))] : []),
      ...(undefinedAt ? [diag('formulaUndefined', { nodeId }, fmt3(undefinedAt))] : []),
    ];
    return { outputs: { seed }, diagnostics, readout: divisor > 1 ? `slope ${fmt(slope)}` : 'a distance' };
  },
  overlay3d: (_ctx, out) =>
    out.seed.kind === 'formula'
      ? [{ shape: 'sphere', sphere: { center: out.seed.center, radius: out.seed.radius } }]
      : [],
  handles3d: ({ inputs }) => sphereHandles({ center: inputs.center, radius: Math.max(0, inputs.radius) }),
  drag3d: (handle, to, ctx) =>
    handle === 'center' ? { center: [...to] } : { radius: radiusTo(ctx.inputs.center, to) },
});
