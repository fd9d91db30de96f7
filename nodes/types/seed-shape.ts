/**
 * Seed shape: an orbit seed (docs/math.md "orbit seeds") whose region is where a formula of the
 * tested point z = (x, y) is negative (docs/formula.md "Seed shapes") — a flower, a star, a
 * crescent, any region people write. The same checked formula tree runs on the CPU and is written
 * out as GLSL (shader-gen/glsl/formula.glsl.ts); a, b, c, p, q and t travel as uniforms, so a drag
 * recompiles nothing, only a new formula text does.
 */

import { defineNode } from '../core/define-node.ts';
import type { SeedSpec } from '../core/tile-spec.ts';
import { formulaFor } from '../formula/checked.ts';
import { SHAPE_NAMES } from '../formula/names.ts';
import { MAX_FORMULA_LENGTH } from '../formula/parse.ts';
import { pointHandles } from './construction-shared.ts';
import { pointInput } from './shared.ts';

/** The default: a five-petal flower of radius about a round p (b petals, c their depth). */
export const FLOWER = 'length(z - p) - a * (1 + c * cos(b * atan2(y - p.y, x - p.x)))';

export const seedShapeNode = defineNode({
  type: 'seed-shape',
  version: 1,
  label: 'Seed shape',
  category: 'Colour',
  color: '#e0b0ff',
  doc:
    'An orbit seed painted where a formula of the point z = (x, y) is negative (a flower by default); ' +
    'a, b, c, p, q and the time t are its values. The tile paints it and all its images.',
  inputs: {
    a: { type: 'number', label: 'a', default: 0.12 },
    b: { type: 'number', label: 'b', default: 5 },
    c: { type: 'number', label: 'c', default: 0.35 },
    p: pointInput('p', 0, 0),
    q: pointInput('q', 1, 0),
    color: { type: 'color', label: 'colour', default: '#ffd166' },
  },
  outputs: { seed: { type: 'seed', label: 'seed' } },
  params: {
    formula: {
      kind: 'string',
      default: FLOWER,
      maxLength: MAX_FORMULA_LENGTH,
      label: 'inside where < 0',
      doc: 'a formula of z (or x, y), a, b, c, p, q, t giving a number: the seed is where it is negative',
    },
  },
  evaluate: ({ nodeId, inputs, params, time }) => {
    const text = params.formula;
    const checked = formulaFor(
      nodeId,
      text,
      SHAPE_NAMES,
      ['number'],
      "a seed shape's formula gives a number (negative inside)",
    );
    if ('problem' in checked) return { diagnostics: [checked.problem] };
    const seed: SeedSpec = {
      kind: 'shape',
      nodeId,
      formula: text,
      numbers: [inputs.a, inputs.b, inputs.c, time],
      points: [inputs.p[0], inputs.p[1], inputs.q[0], inputs.q[1]],
      color: inputs.color,
    };
    return { outputs: { seed } };
  },
  ...pointHandles('p', 'q'),
});
