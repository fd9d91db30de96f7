import { defineNode } from '../core/define-node.ts';
import type { TranslationElement } from '../core/scene-elements.ts';
import type { Vec2 } from '../core/values.ts';
import { GEOMETRY_EPS } from '../geometry/circle.ts';
import { add, cross, dot, len, normalize, perp, scale, sub } from '../geometry/vec.ts';
import { lineAlong, pointHandles } from './construction-shared.ts';
import { fail, fmt, pointInput } from './shared.ts';

/**
 * The strip of the translation by `shift` whose edges run along `other`: normal n ⊥ other,
 * oriented so that shift·n > 0, period D = shift·n. Folding it moves p by multiples of `shift`,
 * which leaves (p − q)·n' of the other strip unchanged (n' ⊥ shift): the two folds commute and the
 * tile is the parallelogram q + s·u + t·v, 0 ≤ s, t < 1.
 */
function latticeStrip(nodeId: string, q: Vec2, shift: Vec2, other: Vec2): TranslationElement {
  const m = normalize(perp(other));
  const n = dot(shift, m) >= 0 ? m : scale(m, -1);
  return { kind: 'translation', nodeId, q, n, period: dot(shift, n), shift };
}

export const latticeNode = defineNode({
  type: 'lattice',
  version: 1,
  label: 'Lattice',
  category: 'Generators',
  color: '#e85d75',
  doc: 'Two translations u and v, folded in one step each: the plane tiled by a parallelogram (wallpaper p1), square, oblique or hexagonal.',
  inputs: {
    origin: pointInput('origin', -0.5, -0.4330127),
    u: { ...pointInput('corner u', 0.5, -0.4330127), doc: 'origin + u: the first translation' },
    v: { ...pointInput('corner v', 0, 0.4330127), doc: 'origin + v: the second translation' },
  },
  outputs: { elements: { type: 'element', label: 'translations' } },
  params: {},
  evaluate: ({ inputs, nodeId }) => {
    const q = inputs.origin;
    const u = sub(inputs.u, q);
    const v = sub(inputs.v, q);
    const area = cross(u, v);
    if (!(Math.abs(area) > GEOMETRY_EPS * Math.max(1, len(u) * len(v)))) {
      return fail('the corners u and v are collinear with the origin (or coincide): no parallelogram');
    }
    const angle = (Math.acos(Math.max(-1, Math.min(1, dot(u, v) / (len(u) * len(v))))) * 180) / Math.PI;
    return {
      outputs: { elements: [latticeStrip(nodeId, q, u, v), latticeStrip(nodeId, q, v, u)] },
      readout: `|u| = ${fmt(len(u))}, |v| = ${fmt(len(v))}, angle ${fmt(angle)}°`,
    };
  },
  overlay: (ctx) => {
    const q = ctx.inputs.origin;
    const u = sub(ctx.inputs.u, q);
    const v = sub(ctx.inputs.v, q);
    return [
      { shape: 'line', line: lineAlong(q, u) },
      { shape: 'line', line: lineAlong(q, v) },
      { shape: 'line', line: lineAlong(add(q, v), u) },
      { shape: 'line', line: lineAlong(add(q, u), v) },
    ];
  },
  ...pointHandles('origin', 'u', 'v'),
});
