/**
 * The classroom triangle: three points, three Line nodes wired corner to corner in a chosen order,
 * a Line reflection on each line, all wired into one Render.
 */
import type { Vec2 } from '../../../nodes/core/values.ts';
import type { GraphDoc } from '../../../nodes/graph/document.ts';
import { doc, edge, node } from '../support/doc.ts';

export const EQUILATERAL: readonly Vec2[] = [
  [-1, -1 / Math.sqrt(3)],
  [1, -1 / Math.sqrt(3)],
  [0, 2 / Math.sqrt(3)],
];

/**
 * Points A, B, C at `corners`, lines from `pairs` (e.g. ['AB', 'AC', 'BC']), mirrors labelled by
 * the pair (with `flip` where listed).
 */
export function triangleDoc(
  corners: readonly Vec2[],
  pairs: readonly string[],
  flipped: readonly string[] = [],
): GraphDoc {
  const nodes = [
    ...['A', 'B', 'C'].map((id, i) => ({
      ...node(id, 'point', { x: corners[i][0], y: corners[i][1] }),
      label: id,
    })),
    ...pairs.map((p) => node(`line${p}`, 'line')),
    ...pairs.map((p) => ({
      ...node(`m${p}`, 'reflection', flipped.includes(p) ? { flip: true } : {}),
      label: p,
    })),
    node('out', 'render'),
  ];
  const edges = pairs.flatMap((p) => [
    edge(`a${p}`, `${p[0]}.point`, `line${p}.a`),
    edge(`b${p}`, `${p[1]}.point`, `line${p}.b`),
    edge(`l${p}`, `line${p}.line`, `m${p}.line`),
    edge(`r${p}`, `m${p}.element`, 'out.elements'),
  ]);
  return doc(nodes, edges);
}
