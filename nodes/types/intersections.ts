/**
 * Intersections of lines and circles. No intersection is a warning (the outputs have no value,
 * so nodes wired to them say why); a tangency gives the touching point on both outputs.
 */
import { defineNode, type EvalOutcome, type OutputSpecs } from '../core/define-node.ts';
import { diag } from '../core/diagnostics.ts';
import type { Vec2 } from '../core/values.ts';
import { isDegenerateLine } from '../geometry/circle.ts';
import {
  type Intersection,
  intersectCircles,
  intersectLineCircle,
  intersectLines,
} from '../geometry/intersect.ts';
import { nearlyEqual } from '../geometry/vec.ts';
import { fail, VISIBLE } from './shared.ts';

/** Outcome with outputs p1, p2, or a warning and no outputs. */
function twoPoints(x: Intersection): EvalOutcome<{ p1?: Vec2; p2?: Vec2 }> {
  if (!x.ok)
    return { outputs: {}, diagnostics: [diag('noIntersection', {}, x.reason)], readout: 'no intersection' };
  const [p1, p2] = x.points;
  return { outputs: { p1, p2 }, readout: nearlyEqual(p1, p2, 1e-12) ? 'tangent: one point' : 'two points' };
}

const pointOverlay = (
  _ctx: unknown,
  out: { readonly p1?: Vec2; readonly p2?: Vec2; readonly point?: Vec2 },
) => [out.p1, out.p2, out.point].flatMap((at) => (at ? [{ shape: 'point' as const, at }] : []));

const lineInput = (label: string, a: Vec2, b: Vec2) => ({ type: 'line' as const, label, default: { a, b } });
const circleInput = (label: string, c: Vec2, r: number) => ({
  type: 'circle' as const,
  label,
  default: { c, r },
});
/** Both are empty when the two miss each other (a warning, not an error). */
const points = {
  p1: { type: 'point', label: 'p1', optional: true },
  p2: { type: 'point', label: 'p2', optional: true },
} as const satisfies OutputSpecs;
const noLine = 'a line has no direction (its two points coincide)';
const noCircle = 'a circle needs a positive radius';

export const intersectLinesNode = defineNode({
  type: 'intersect-lines',
  version: 1,
  label: 'Line ∩ line',
  category: 'Construction',
  color: '#f2c14e',
  doc: 'The point where two lines cross (a warning when they are parallel).',
  inputs: { l1: lineInput('line 1', [-1, -1], [1, 1]), l2: lineInput('line 2', [-1, 1], [1, -1]) },
  outputs: { point: { type: 'point', label: 'point', optional: true } },
  params: { visible: VISIBLE },
  evaluate: ({ inputs }) => {
    const { l1, l2 } = inputs;
    if (isDegenerateLine(l1) || isDegenerateLine(l2)) return fail(noLine);
    const x = intersectLines(l1, l2);
    if (!x.ok)
      return { outputs: {}, diagnostics: [diag('noIntersection', {}, x.reason)], readout: 'no intersection' };
    return { outputs: { point: x.points[0] } };
  },
  overlay: pointOverlay,
});

export const intersectLineCircleNode = defineNode({
  type: 'intersect-line-circle',
  version: 1,
  label: 'Line ∩ circle',
  category: 'Construction',
  color: '#f2c14e',
  doc: "Where a line meets a circle: p1 then p2 in the line's direction (equal when tangent; a warning when they miss).",
  inputs: { line: lineInput('line', [-2, 0.3], [2, 0.3]), circle: circleInput('circle', [0, 0], 1) },
  outputs: points,
  params: { visible: VISIBLE },
  evaluate: ({ inputs }) => {
    const { line, circle } = inputs;
    if (isDegenerateLine(line)) return fail(noLine);
    if (!(circle.r > 0)) return fail(noCircle);
    return twoPoints(intersectLineCircle(line, circle));
  },
  overlay: pointOverlay,
});

export const intersectCirclesNode = defineNode({
  type: 'intersect-circles',
  version: 1,
  label: 'Circle ∩ circle',
  category: 'Construction',
  color: '#f2c14e',
  doc: 'Where two circles meet: p1 right and p2 left of the line from centre 1 to centre 2 (equal when tangent).',
  inputs: { c1: circleInput('circle 1', [-0.5, 0], 1), c2: circleInput('circle 2', [0.5, 0], 1) },
  outputs: points,
  params: { visible: VISIBLE },
  evaluate: ({ inputs }) => {
    const { c1, c2 } = inputs;
    if (!(c1.r > 0 && c2.r > 0)) return fail(noCircle);
    return twoPoints(intersectCircles(c1, c2));
  },
  overlay: pointOverlay,
});
