import { defineNode } from '../core/define-node.ts';
import type { InversionElement } from '../core/scene-elements.ts';
import { hyperbolicPolygonMirrors, isHyperbolicPolygon } from '../geometry/hyperbolic-polygon.ts';
import { angleInput } from './construction-shared.ts';
import { fail, fmt } from './shared.ts';

export const hyperbolicPolygonNode = defineNode({
  type: 'hyperbolic-polygon',
  version: 1,
  label: 'Hyperbolic polygon',
  category: 'Kaleidoscopes',
  color: '#c06c84',
  doc: 'A regular n-gon with angles 180°/q in the Poincaré disk, bounded by n circular mirrors: tiles the disk with n-gons, 2q around each vertex.',
  inputs: {
    n: { type: 'number', label: 'sides n', default: 5, min: 3, max: 64, integer: true },
    q: {
      type: 'number',
      label: 'angle 180°/q',
      default: 3,
      min: 2,
      max: 64,
      integer: true,
      doc: 'interior angle π/q',
    },
    rotation: angleInput('turn (°)', 0, 'direction of the first edge’s midpoint, counter-clockwise from +x'),
  },
  outputs: {
    elements: { type: 'element', label: 'mirrors' },
    boundary: {
      type: 'circle',
      label: 'disk',
      doc: 'the unit circle (the Poincaré disk), to wire into the render’s clip',
    },
  },
  params: {},
  evaluate: ({ inputs, nodeId }) => {
    const { n, q } = inputs;
    if (!isHyperbolicPolygon(n, q)) {
      const kind = (n - 2) * (q - 1) === 2 ? 'Euclidean' : 'spherical';
      return fail(
        `an ${n}-gon with angles 180°/${q} is ${kind}, not hyperbolic: needs (n − 2)(q − 1) > 2 (try more sides or a larger q)`,
      );
    }
    const rot = (inputs.rotation * Math.PI) / 180;
    const elements = hyperbolicPolygonMirrors(n, q, rot).map(
      (m): InversionElement => ({ kind: 'inversion', nodeId, c: m.c, r: m.r }),
    );
    return {
      outputs: { elements, boundary: { c: [0, 0], r: 1 } },
      readout: `{${n}, ${2 * q}}: ${n}-gons with ${fmt(180 / q)}° angles, ${2 * q} at each vertex`,
    };
  },
  overlay: (_ctx, out) =>
    // Every element is an inversion (evaluate makes only those); the guard keeps the type exact.
    out.elements.flatMap((e) =>
      e.kind === 'inversion' ? [{ shape: 'circle' as const, circle: { c: e.c, r: e.r } }] : [],
    ),
});
