/** Small documents shared by the overlay tests (unit tests and the Chromium page). */
import type { GraphDoc, GraphEdge, GraphNode } from '../../../../nodes/graph/document.ts';

export const node = (
  id: string,
  type: string,
  params: Record<string, unknown> = {},
  label?: string,
): GraphNode => ({
  id,
  type,
  position: [0, 0],
  params,
  ...(label ? { label } : {}),
});

export const edge = (from: string, fromPort: string, to: string, toPort: string): GraphEdge => ({
  id: `${from}.${fromPort}->${to}.${toPort}`,
  from: { node: from, port: fromPort },
  to: { node: to, port: toPort },
});

export const doc = (nodes: GraphNode[], edges: GraphEdge[] = []): GraphDoc => ({
  format: 'kleinflow',
  version: 1,
  meta: { title: 'overlay test' },
  nodes,
  edges,
  view: { center: [0, 0], scale: 4 },
});

/**
 * The browser test's construction: a free circle c1 (centre (0,0), r 1), a hidden point p1 at
 * (1, 1) wired into the centre of circle c2 (r 0.5) — so c2's centre handle is the one drawn there
 * and its drag must move p1 — and a loose point p2 at (−1, 1).
 */
export const overlayDoc = (): GraphDoc =>
  doc(
    [
      node('c1', 'circle', { center: [0, 0], radius: 1 }, 'C'),
      node('p1', 'point', { x: 1, y: 1, visible: false }, 'P'),
      node('c2', 'circle', { center: [5, 5], radius: 0.5 }),
      node('p2', 'point', { x: -1, y: 1 }),
    ],
    [edge('p1', 'point', 'c2', 'center')],
  );
