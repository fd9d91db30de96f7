import { defineNode } from '../core/define-node.ts';
import type { RotationElement } from '../core/scene-elements.ts';
import type { Vec2 } from '../core/values.ts';
import { add, rotate, sub } from '../geometry/vec.ts';
import { angleInput, degreesOf, lineAlong, unitFromDegrees } from './construction-shared.ts';
import { fmt, pointInput } from './shared.ts';

/** The wedge's two rays, from the centre along b1 and along b1 turned by 2π/order. */
const wedge = (inputs: { readonly center: Vec2; readonly angle: number; readonly order: number }) => {
  const c = inputs.center;
  const b1 = unitFromDegrees(inputs.angle);
  return { c, b1, b2: rotate(b1, (2 * Math.PI) / inputs.order) };
};

export const rotationNode = defineNode({
  type: 'rotation',
  version: 1,
  label: 'Rotation',
  category: 'Generators',
  color: '#e85d75',
  doc: 'A rotation of order k about a centre, folded in one step: the wedge of angle 360°/k is the tile.',
  inputs: {
    center: pointInput('centre', 0, 0),
    order: {
      type: 'number',
      label: 'order k',
      default: 6,
      min: 2,
      max: 360,
      integer: true,
      doc: 'rotation by 360°/k',
    },
    angle: angleInput('start (°)', 0, 'direction of the wedge’s first ray, counter-clockwise from +x'),
  },
  outputs: { element: { type: 'element', label: 'element' } },
  params: {},
  evaluate: ({ inputs, nodeId }) => {
    const { c, b1 } = wedge(inputs);
    const order = inputs.order;
    const element: RotationElement = { kind: 'rotation', nodeId, c, b1, order };
    return { outputs: { element: [element] }, readout: `order ${order}: wedge of ${fmt(360 / order)}°` };
  },
  overlay: (ctx) => {
    const { c, b1, b2 } = wedge(ctx.inputs);
    return [
      { shape: 'point', at: c },
      { shape: 'line', line: lineAlong(c, b1) },
      { shape: 'line', line: lineAlong(c, b2) },
    ];
  },
  handles: (ctx) => {
    const { c, b1 } = wedge(ctx.inputs);
    return [
      { handle: 'center', at: c },
      { handle: 'direction', at: add(c, b1) },
    ];
  },
  drag: (handle, to, ctx) =>
    handle === 'center' ? { center: [...to] } : { angle: degreesOf(sub(to, ctx.inputs.center)) },
});
