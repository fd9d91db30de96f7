import { defineNode } from '../core/define-node.ts';
import type { ReflectionElement } from '../core/scene-elements.ts';
import type { Vec2 } from '../core/values.ts';
import { add, perp, rotate, scale, sub } from '../geometry/vec.ts';
import { angleInput, degreesOf, lineAlong, unitFromDegrees } from './construction-shared.ts';
import { fmt, pointInput } from './shared.ts';

/**
 * The two mirror directions: u (the start ray) and v = u turned by π/k. Mirror 1 keeps the left of
 * u (normal perp(u)), mirror 2 the right of v (normal −perp(v)): together they keep the wedge of
 * angle π/k between u and v (docs/math.md: orient them so, or the kept region is the π − π/k wedge).
 */
const mirrors = (inputs: { readonly center: Vec2; readonly angle: number; readonly k: number }) => {
  const c = inputs.center;
  const u = unitFromDegrees(inputs.angle);
  const v = rotate(u, Math.PI / inputs.k);
  return { c, u, v };
};

export const kMirrorNode = defineNode({
  type: 'k-mirror',
  version: 1,
  label: 'k-mirror kaleidoscope',
  category: 'Kaleidoscopes',
  color: '#c06c84',
  doc: 'Two mirrors through a centre at angle 180°/k: the classic kaleidoscope with 2k copies of a wedge (dihedral symmetry *kk).',
  inputs: {
    center: pointInput('centre', 0, 0),
    k: {
      type: 'number',
      label: 'k',
      default: 5,
      min: 1,
      max: 360,
      integer: true,
      doc: 'the mirrors meet at 180°/k',
    },
    angle: angleInput('start (°)', 0, 'direction of the first mirror, counter-clockwise from +x'),
  },
  outputs: { elements: { type: 'element', label: 'mirrors' } },
  params: {},
  evaluate: ({ inputs, nodeId }) => {
    const { c, u, v } = mirrors(inputs);
    const k = inputs.k;
    const m1: ReflectionElement = { kind: 'reflection', nodeId, q: c, n: perp(u) };
    const m2: ReflectionElement = { kind: 'reflection', nodeId, q: c, n: scale(perp(v), -1) };
    return { outputs: { elements: [m1, m2] }, readout: `*${k}${k}: ${2 * k} wedges of ${fmt(180 / k)}°` };
  },
  overlay: (ctx) => {
    const { c, u, v } = mirrors(ctx.inputs);
    return [
      { shape: 'line', line: lineAlong(c, u) },
      { shape: 'line', line: lineAlong(c, v) },
    ];
  },
  handles: (ctx) => {
    const { c, u } = mirrors(ctx.inputs);
    return [
      { handle: 'center', at: c },
      { handle: 'direction', at: add(c, u) },
    ];
  },
  drag: (handle, to, ctx) =>
    handle === 'center' ? { center: [...to] } : { angle: degreesOf(sub(to, ctx.inputs.center)) },
});
