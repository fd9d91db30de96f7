/**
 * The strip generators (closed-form elements, docs/math.md): translation, parallel mirrors and glide
 * reflection. Each acts across the strip 0 ≤ (p − origin)·n < period, n the unit direction.
 */
import { defineNode } from '../core/define-node.ts';
import type { SceneElement, StripData } from '../core/scene-elements.ts';
import type { Line, Vec2 } from '../core/values.ts';
import { add, dot, perp, scale, sub } from '../geometry/vec.ts';
import { angleInput, degreesOf, lineAlong, unitFromDegrees } from './construction-shared.ts';
import { fail, fmt, pointInput } from './shared.ts';

type StripKind = 'translation' | 'parallel-mirrors' | 'glide-reflection';

/** Smallest period a drag may set (keeps the strip valid while the edge is dragged past the origin). */
const MIN_PERIOD = 1e-3;

const stripData = (inputs: { readonly origin: Vec2; readonly angle: number; readonly period: number }) => ({
  q: inputs.origin,
  n: unitFromDegrees(inputs.angle),
  period: inputs.period,
});

/** The strip's two edges h = 0 and h = D (lines along perp(n)). */
const stripEdges = ({ q, n, period }: StripData): Line[] => [
  lineAlong(q, perp(n)),
  lineAlong(add(q, scale(n, period)), perp(n)),
];

function stripNode(kind: StripKind, label: string, doc: string, what: string) {
  return defineNode({
    type: kind,
    version: 1,
    label,
    category: kind === 'parallel-mirrors' ? 'Kaleidoscopes' : 'Generators',
    color: '#e85d75',
    doc,
    inputs: {
      origin: { ...pointInput('origin', -0.5, 0), doc: 'a point on the first edge of the tile strip' },
      angle: angleInput('direction (°)', 0, `direction n of the ${what}, counter-clockwise from +x`),
      period: {
        type: 'number',
        label: 'period',
        default: 1,
        min: 0,
        step: 0.01,
        doc: 'the width D of the tile strip',
      },
    },
    outputs: { element: { type: 'element', label: 'element' } },
    params: {},
    evaluate: ({ inputs, nodeId }) => {
      const data = stripData(inputs);
      if (!(data.period > 0)) return fail(`the period must be positive, got ${fmt(data.period)}`);
      const element: SceneElement = { kind, nodeId, ...data };
      return {
        outputs: { element: [element] },
        readout: `period ${fmt(data.period)} along ${fmt(inputs.angle)}°`,
      };
    },
    overlay: (ctx) => {
      const data = stripData(ctx.inputs);
      const edges = stripEdges(data).map((line) => ({ shape: 'line' as const, line }));
      // The glide axis: the line through the origin along n, which odd steps reflect across.
      return kind === 'glide-reflection'
        ? [...edges, { shape: 'line' as const, line: lineAlong(data.q, data.n) }]
        : edges;
    },
    handles: (ctx) => {
      const { q, n, period } = stripData(ctx.inputs);
      return [
        { handle: 'origin', at: q },
        { handle: 'edge', at: add(q, scale(n, period)) },
        { handle: 'turn', at: add(q, scale(perp(n), period)) },
      ];
    },
    drag: (handle, to, ctx) => {
      const { q, n } = stripData(ctx.inputs);
      if (handle === 'origin') return { origin: [...to] };
      // The far edge moves along n: the period is its height above the origin.
      if (handle === 'edge') return { period: Math.max(MIN_PERIOD, dot(sub(to, q), n)) };
      // The turn handle sits on the first edge (along perp(n)): n points 90° clockwise of it.
      return { angle: degreesOf(sub(to, q)) - 90 };
    },
  });
}

export const translationNode = stripNode(
  'translation',
  'Translation strip',
  'A translation by a period, folded in one step: copies of a strip (a frieze); two strips at right angles tile the plane (a wallpaper).',
  'translation',
);

export const parallelMirrorsNode = stripNode(
  'parallel-mirrors',
  'Parallel mirrors',
  'Two parallel mirrors a period apart, folded in one step: the strip and its reflections.',
  'normal to the mirrors',
);

export const glideReflectionNode = stripNode(
  'glide-reflection',
  'Glide reflection',
  'A glide reflection (translate by a period, then reflect in the axis through the origin), folded in one step.',
  'glide',
);
