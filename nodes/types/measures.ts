/** Measurements as number outputs (wire them into any number input): an angle and a distance. */
import { defineNode } from '../core/define-node.ts';
import { cross, dist, dot, sub } from '../geometry/vec.ts';
import { lineAlong, pointHandles } from './construction-shared.ts';
import { degrees, fail, fmt, pointInput, VISIBLE } from './shared.ts';

/** Distances this small count as "the same point" for the angle. */
const SAME_POINT = 1e-12;

export const angleNode = defineNode({
  type: 'angle',
  version: 1,
  label: 'Angle',
  category: 'Construction',
  color: '#9aa5b1',
  doc: 'The angle at vertex b between the rays to a and c (0 to π), as radians and as degrees.',
  inputs: { a: pointInput('a', 1, 0), b: pointInput('vertex b', 0, 0), c: pointInput('c', 0, 1) },
  outputs: {
    angle: { type: 'number', label: 'radians' },
    degrees: {
      type: 'number',
      label: 'degrees',
      doc: 'the same angle in degrees, for the nodes whose angle inputs are in degrees',
    },
  },
  params: { visible: VISIBLE },
  evaluate: ({ inputs }) => {
    const b = inputs.b;
    const u = sub(inputs.a, b);
    const v = sub(inputs.c, b);
    if (Math.hypot(...u) <= SAME_POINT || Math.hypot(...v) <= SAME_POINT) {
      return fail('a or c coincides with the vertex b: the angle is undefined');
    }
    // atan2(|u × v|, u·v): accurate for small and near-straight angles alike (acos is not).
    const angle = Math.atan2(Math.abs(cross(u, v)), dot(u, v));
    return { outputs: { angle, degrees: (angle * 180) / Math.PI }, readout: degrees(angle) };
  },
  overlay: (ctx) => {
    const b = ctx.inputs.b;
    return [
      { shape: 'line', line: lineAlong(b, sub(ctx.inputs.a, b)) },
      { shape: 'line', line: lineAlong(b, sub(ctx.inputs.c, b)) },
    ];
  },
  ...pointHandles('a', 'b', 'c'),
});

export const distanceNode = defineNode({
  type: 'distance',
  version: 1,
  label: 'Distance',
  category: 'Construction',
  color: '#9aa5b1',
  doc: 'The distance |b − a| between two points.',
  inputs: { a: pointInput('a', 0, 0), b: pointInput('b', 1, 0) },
  outputs: { distance: { type: 'number', label: 'distance' } },
  params: { visible: VISIBLE },
  evaluate: ({ inputs }) => {
    const d = dist(inputs.a, inputs.b);
    return { outputs: { distance: d }, readout: fmt(d) };
  },
  overlay: (ctx) => [
    { shape: 'point', at: ctx.inputs.a },
    { shape: 'point', at: ctx.inputs.b },
  ],
  ...pointHandles('a', 'b'),
});
