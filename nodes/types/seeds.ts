/**
 * Orbit seeds (docs/math.md "orbit seeds", the paper's Figs. 2 and 11): shapes placed in the plane whose
 * images under the whole IIS the tile paints. Wire them into the tile's `seeds` input.
 */
import { defineNode } from '../core/define-node.ts';
import type { SeedSpec } from '../core/tile-spec.ts';
import { BUILTIN_PICTURE, type Vec2 } from '../core/values.ts';
import { dist } from '../geometry/vec.ts';
import { fail, fmt, pointInput } from './shared.ts';

export const seedDiskNode = defineNode({
  type: 'seed-disk',
  version: 1,
  label: 'Seed disk',
  category: 'Colour',
  color: '#e0b0ff',
  doc: 'An orbit seed: a coloured disk; the tile paints it and all its images (the paper’s Fig. 2).',
  inputs: {
    circle: {
      type: 'circle',
      label: 'disk',
      default: { c: [0, 0], r: 0.1 },
      doc: 'the seed disk (wire a circle, or edit it here)',
    },
    color: { type: 'color', label: 'colour', default: '#ffd166' },
  },
  outputs: { seed: { type: 'seed', label: 'seed' } },
  params: {},
  evaluate: ({ inputs, nodeId }) => {
    const { c, r } = inputs.circle;
    if (!(r > 0)) return fail(`the seed disk's radius must be positive, got ${fmt(r)}`);
    const seed: SeedSpec = { kind: 'disk', nodeId, c, r, color: inputs.color };
    return { outputs: { seed }, readout: `r = ${fmt(r)}` };
  },
  // The circle comes from the inputs: the seed output is the same disk (evaluate copies it).
  overlay: ({ inputs }) => [{ shape: 'circle', circle: inputs.circle }],
  handles: ({ inputs }) => {
    const { c, r } = inputs.circle;
    return [
      { handle: 'center', at: c },
      { handle: 'rim', at: [c[0] + r, c[1]] },
    ];
  },
  drag: (handle, to, ctx) => {
    const { c, r } = ctx.inputs.circle;
    return handle === 'center'
      ? { circle: { c: [...to], r } }
      : { circle: { c: [...c], r: Math.max(1e-6, dist(c, to)) } };
  },
});

const rad = (deg: number) => (deg * Math.PI) / 180;

/** The rectangle's corner handle: centre + R(θ)(w/2, h/2). */
const cornerOf = (c: Vec2, w: number, h: number, theta: number): Vec2 => [
  c[0] + Math.cos(theta) * (w / 2) - Math.sin(theta) * (h / 2),
  c[1] + Math.sin(theta) * (w / 2) + Math.cos(theta) * (h / 2),
];

export const seedImageNode = defineNode({
  type: 'seed-image',
  version: 1,
  label: 'Seed picture',
  category: 'Colour',
  color: '#e0b0ff',
  doc: 'An orbit seed: a picture in a rectangle (centre, width, height, rotation); the tile paints it and all its images (the paper’s Fig. 11).',
  inputs: {
    image: { type: 'image', label: 'picture', optional: true, doc: 'the built-in checker when unwired' },
    center: pointInput('centre', 0, 0),
    width: { type: 'number', label: 'width', default: 0.3, min: 0, step: 0.01 },
    height: { type: 'number', label: 'height', default: 0.3, min: 0, step: 0.01 },
    rotation: { type: 'number', label: 'rotation °', default: 0, step: 1 },
  },
  outputs: { seed: { type: 'seed', label: 'seed' } },
  params: {},
  evaluate: ({ inputs, nodeId }) => {
    const { width, height } = inputs;
    if (!(width > 0 && height > 0))
      return fail(`the seed rectangle needs a positive size, got ${fmt(width)} × ${fmt(height)}`);
    const seed: SeedSpec = {
      kind: 'image',
      nodeId,
      center: inputs.center,
      width,
      height,
      rotation: rad(inputs.rotation),
      image: inputs.image ?? BUILTIN_PICTURE,
    };
    return { outputs: { seed }, readout: `${fmt(width)} × ${fmt(height)}` };
  },
  // Drawn from the inputs, which the seed output copies (the rotation in radians).
  overlay: ({ inputs }) => [{ shape: 'point', at: inputs.center }],
  handles: ({ inputs: s }) => [
    { handle: 'center', at: s.center },
    { handle: 'corner', at: cornerOf(s.center, s.width, s.height, rad(s.rotation)) },
  ],
  /** The corner keeps the aspect ratio: it scales the rectangle and turns it about the centre. */
  drag: (handle, to, ctx) => {
    if (handle === 'center') return { center: [...to] };
    const { center: c, width: w, height: h } = ctx.inputs;
    const half = Math.hypot(w, h) / 2;
    const k = Math.max(1e-6, dist(c, to)) / half;
    const turn = Math.atan2(to[1] - c[1], to[0] - c[0]) - Math.atan2(h, w);
    return { width: w * k, height: h * k, rotation: (turn * 180) / Math.PI };
  },
});
