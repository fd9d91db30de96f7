import { defineNode } from '../core/define-node.ts';
import type { OverlayShape } from '../core/overlay.ts';
import type { InversionElement, ReflectionElement, SceneElement } from '../core/scene-elements.ts';
import type { Circle, Vec2 } from '../core/values.ts';
import { triangleGeometry, triangleMirrors } from '../geometry/triangle.ts';
import { fail } from './shared.ts';

const order = (label: string, dflt: number, allowInfinity: boolean) =>
  ({
    type: 'number',
    label,
    default: dflt,
    min: allowInfinity ? 0 : 2,
    max: 64,
    integer: true,
    doc: allowInfinity ? 'angle π/n; 0 means ∞ (an ideal vertex)' : 'angle π/n',
  }) as const;

/** The (p, q, r) notation with ∞ for 0. */
const name = (n: number) => (n === 0 ? '∞' : String(n));

export const kaleidoscopeNode = defineNode({
  type: 'kaleidoscope',
  version: 1,
  label: 'Triangle kaleidoscope',
  category: 'Kaleidoscopes',
  color: '#c06c84',
  doc: 'The three mirrors of the (p, q, r) triangle group: spherical, Euclidean or hyperbolic, chosen by 1/p+1/q+1/r.',
  inputs: {
    p: order('p', 2, false),
    q: order('q', 3, true),
    r: order('r', 7, true),
    size: {
      type: 'number',
      label: 'size',
      default: 1,
      min: 0,
      step: 0.01,
      doc: 'Euclidean case: distance of mirror 3 from the origin',
    },
  },
  outputs: {
    elements: { type: 'element', label: 'mirrors' },
    boundary: {
      type: 'circle',
      label: 'disk',
      doc: 'the unit circle (the Poincaré disk) in the hyperbolic case',
      optional: true,
    },
  },
  params: {},
  evaluate: ({ inputs, nodeId }) => {
    const { p, q, r, size } = inputs;
    if (q === 1 || r === 1) return fail('q and r must be 2 or more (or 0 for ∞)');
    const geometry = triangleGeometry(p, q, r);
    if (geometry === 'euclidean' && !(size > 0))
      return fail('size must be positive for a Euclidean kaleidoscope');
    const m = triangleMirrors(p, q, r, size);
    const refl = (l: { q: Vec2; n: Vec2 }): ReflectionElement => ({
      kind: 'reflection',
      nodeId,
      q: l.q,
      n: l.n,
    });
    const third: SceneElement =
      m.mirror3.kind === 'line'
        ? refl(m.mirror3)
        : ({ kind: 'inversion', nodeId, c: m.mirror3.c, r: m.mirror3.r } satisfies InversionElement);
    const elements = [refl(m.line1), refl(m.line2), third];
    const boundary: Circle | undefined = geometry === 'hyperbolic' ? { c: [0, 0], r: 1 } : undefined;
    return { outputs: { elements, boundary }, readout: `${geometry} (${name(p)}, ${name(q)}, ${name(r)})` };
  },
  overlay: (_ctx, out) =>
    out.elements.map(
      (e): OverlayShape =>
        e.kind === 'inversion'
          ? { shape: 'circle', circle: { c: e.c, r: e.r } }
          : e.kind === 'reflection'
            ? { shape: 'line', line: { a: e.q, b: [e.q[0] - e.n[1], e.q[1] + e.n[0]] } }
            : { shape: 'point', at: [0, 0] },
    ),
});
