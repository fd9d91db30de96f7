/** Points constructed from others: midpoint, image in a circle, mirror image in a line. */
import { defineNode, type OutputSpecs } from '../core/define-node.ts';
import type { Vec2 } from '../core/values.ts';
import { invertPoint, isDegenerateLine, lineNormal, reflectPoint } from '../geometry/circle.ts';
import { lerp } from '../geometry/vec.ts';
import { pointHandles } from './construction-shared.ts';
import { fail, pointInput, VISIBLE } from './shared.ts';

const pointOut = { point: { type: 'point', label: 'point' } } as const satisfies OutputSpecs;
const pointOverlay = (_ctx: unknown, out: { readonly point: Vec2 }) => [
  { shape: 'point' as const, at: out.point },
];

export const midpointNode = defineNode({
  type: 'midpoint',
  version: 1,
  label: 'Midpoint',
  category: 'Construction',
  color: '#f2c14e',
  doc: 'The point halfway between a and b: (a + b)/2.',
  inputs: { a: pointInput('a', -1, 0), b: pointInput('b', 1, 0) },
  outputs: pointOut,
  params: { visible: VISIBLE },
  evaluate: ({ inputs }) => ({ outputs: { point: lerp(inputs.a, inputs.b, 0.5) } }),
  overlay: pointOverlay,
  ...pointHandles('a', 'b'),
});

export const invertPointNode = defineNode({
  type: 'invert-point',
  version: 1,
  label: 'Invert point',
  category: 'Construction',
  color: '#f2c14e',
  doc: "A point's image in a circle: c + r²(p − c)/|p − c|² (the centre has no image).",
  inputs: {
    circle: { type: 'circle', label: 'circle', default: { c: [0, 0], r: 1 } },
    point: pointInput('p', 0.5, 0.3),
  },
  outputs: pointOut,
  params: { visible: VISIBLE },
  evaluate: ({ inputs }) => {
    const { circle, point } = inputs;
    if (!(circle.r > 0)) return fail('the circle needs a positive radius');
    const image = invertPoint(circle, point);
    if (!image) return fail("the point is the circle's centre: its image is at infinity");
    return { outputs: { point: image } };
  },
  overlay: pointOverlay,
  ...pointHandles('point'),
});

export const reflectPointNode = defineNode({
  type: 'reflect-point',
  version: 1,
  label: 'Reflect point',
  category: 'Construction',
  color: '#f2c14e',
  doc: "A point's mirror image in a line: p − 2((p − q)·n) n.",
  inputs: {
    line: { type: 'line', label: 'line', default: { a: [0, -1], b: [0, 1] } },
    point: pointInput('p', 0.5, 0.3),
  },
  outputs: pointOut,
  params: { visible: VISIBLE },
  evaluate: ({ inputs }) => {
    const { line, point } = inputs;
    if (isDegenerateLine(line)) return fail('the line has no direction (its two points coincide)');
    return { outputs: { point: reflectPoint(line.a, lineNormal(line), point) } };
  },
  overlay: pointOverlay,
  ...pointHandles('point'),
});
