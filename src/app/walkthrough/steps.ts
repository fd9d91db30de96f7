/**
 * The guided walkthrough "build a kaleidoscope step by step": the *333 kaleidoscope from three
 * points, three lines, three mirrors and a Render node. Each step is a check of the live document
 * and its evaluation, so the walkthrough ticks a step off the moment the user has done it, in any
 * order and by any means (palette, paste, undo).
 */

import { depthInSide } from '../../../nodes/geometry/kept-region.ts';
import type { GraphDoc } from '../../../nodes/graph/document.ts';
import type { Evaluation } from '../../../nodes/graph/evaluate.ts';
import { keptSideOf } from '../../../nodes/graph/mirror-check.ts';

export interface WalkthroughStep {
  readonly id: string;
  readonly title: string;
  readonly how: string;
}

export interface StepStatus {
  readonly done: boolean;
  /** What is still missing or wrong, in the user's words (absent when done). */
  readonly todo?: string;
  /** Mirrors whose `flip` would fix the step (the panel offers a one-click fix). */
  readonly flip?: readonly string[];
}

export const WALKTHROUGH: readonly WalkthroughStep[] = [
  {
    id: 'points',
    title: 'Place three points',
    how: 'Press Space, type “point”, Enter — three times. Drag them in the picture to make a triangle.',
  },
  {
    id: 'lines',
    title: 'Join them with three lines',
    how: 'Add three Line nodes and wire the points into a and b going round anticlockwise: A→B, B→C, C→A. A line keeps its left side.',
  },
  {
    id: 'mirrors',
    title: 'Turn each line into a mirror',
    how: 'Add a Line reflection for each line and wire the line into it.',
  },
  {
    id: 'render',
    title: 'Wire the mirrors into Render',
    how: 'Add a Render node and wire all three mirrors into its “elements” socket.',
  },
  {
    id: 'inside',
    title: 'Every mirror keeps the inside',
    how: 'Each mirror must keep the triangle’s side. If one keeps the outside, tick its “flip”.',
  },
];

const wiredFrom = (doc: GraphDoc, nodeId: string, port: string) =>
  doc.edges.filter((e) => e.to.node === nodeId && e.to.port === port).map((e) => e.from.node);

const typeOf = (doc: GraphDoc, id: string) => doc.nodes.find((n) => n.id === id)?.type;

const plural = (n: number, one: string) => `${n} ${one}${n === 1 ? '' : 's'}`;

/** The status of every step, in order. */
export function walkthroughStatus(doc: GraphDoc, evaluation: Evaluation): readonly StepStatus[] {
  const ofType = (t: string) => doc.nodes.filter((n) => n.type === t);
  const points = ofType('point').length;
  const lines = ofType('line').filter((l) =>
    ['a', 'b'].every((port) => wiredFrom(doc, l.id, port).some((from) => typeOf(doc, from) === 'point')),
  );
  const mirrors = ofType('reflection').filter((r) =>
    wiredFrom(doc, r.id, 'line').some((from) => typeOf(doc, from) === 'line'),
  );
  const mirrorIds = new Set(mirrors.map((m) => m.id));
  const render = ofType('render')
    .map((r) => wiredFrom(doc, r.id, 'elements').filter((from) => mirrorIds.has(from)).length)
    .reduce((a, b) => Math.max(a, b), 0);
  const outside = mirrorsKeepingOutside(doc, evaluation);

  return [
    points >= 3 ? { done: true } : { done: false, todo: `${plural(points, 'point')} so far` },
    lines.length >= 3
      ? { done: true }
      : { done: false, todo: `${plural(lines.length, 'line')} with both ends wired to points` },
    mirrors.length >= 3
      ? { done: true }
      : { done: false, todo: `${plural(mirrors.length, 'mirror')} with a line wired in` },
    render >= 3 ? { done: true } : { done: false, todo: `${plural(render, 'mirror')} wired into Render` },
    render >= 3 && outside.length === 0 && evaluation.scene.elements.length >= 3
      ? { done: true }
      : outside.length > 0
        ? {
            done: false,
            todo: `${outside.map((m) => m.name).join(', ')} keep${outside.length === 1 ? 's' : ''} the outside: tick “flip”`,
            flip: outside.map((m) => m.id),
          }
        : { done: false, todo: 'wire three mirrors into Render first' },
  ];
}

/**
 * The rendered line mirrors whose kept side (p − q)·n ≥ 0 does not contain the centroid of the
 * document's points (the triangle's inside when the points are its corners), named as the user
 * sees them: the node's label, or "Line reflection N" counting those nodes in document order.
 * The Render's KF406 warning (nodes/graph/mirror-check.ts) says the same with a fix; this names
 * them per step.
 */
function mirrorsKeepingOutside(doc: GraphDoc, evaluation: Evaluation): { id: string; name: string }[] {
  const corners = doc.nodes
    .filter((n) => n.type === 'point')
    .map((n) => evaluation.nodes.get(n.id)?.outputs?.point)
    .filter((p): p is readonly [number, number] => Array.isArray(p));
  if (corners.length < 3) return [];
  const cx = corners.reduce((s, p) => s + p[0], 0) / corners.length;
  const cy = corners.reduce((s, p) => s + p[1], 0) / corners.length;
  return evaluation.scene.elements
    .filter((e) => e.kind === 'reflection')
    .filter((e) => depthInSide(keptSideOf(e)!, [cx, cy]) < 0)
    .map((e) => {
      const reflections = doc.nodes.filter((n) => n.type === 'reflection');
      const i = reflections.findIndex((n) => n.id === e.nodeId);
      return { id: e.nodeId, name: reflections[i]?.label ?? `Line reflection ${i + 1}` };
    });
}
