/**
 * The KF407 fix for a kept region that is a triangle of three line mirrors: ONE snap of the whole
 * triangle (nodes/geometry/triangle-snap.ts) instead of one corner at a time, which never settles
 * because the angles of three straight lines always sum to π. This file maps the graph onto the
 * solver — which free points define each mirror's line, and which node moves each — and words the
 * fix so a teacher knows what will move: "Snap to (2, 3, 6): moves “C” to (0, 1.732)". Pure.
 */

import type { EvalContext } from '../core/define-node.ts';
import type { DiagnosticFix } from '../core/diagnostics.ts';
import type { Line, Vec2 } from '../core/values.ts';
import { type SnapLine, snapTriangle, type TriangleSnap } from '../geometry/triangle-snap.ts';
import type { Analysis } from './analyze.ts';
import { nodeName } from './node-names.ts';

/** What the mirror checks read of an evaluated graph (here, so the angle check and this file share it without a cycle). */
export interface MirrorGraph {
  readonly analysis: Analysis;
  /** Each node's outputs (evaluate.ts's NodeEvaluation, structurally: no import back to it). */
  readonly nodes: ReadonlyMap<
    string,
    { readonly outputs?: Readonly<Record<string, unknown>>; readonly ctx?: EvalContext }
  >;
}

/** One point a mirror's line is defined by, and how the fix moves it. */
interface LinePoint {
  readonly id: string;
  readonly at: Vec2;
  readonly free: boolean;
  readonly name: string;
  /** Document position of the node that holds it: earlier points are kept first. */
  readonly rank: number;
  /** A Line node's handle (moved like a drag: the wired point node follows), or a mirror's own line. */
  readonly via:
    | { readonly lineNode: string; readonly handle: 'a' | 'b' }
    | { readonly mirror: string; readonly handle: 'a' | 'b' };
}

/** Where the line mirror `mirrorId` gets its line: a Line node (`owner`), or its own `line` param (null). */
export function lineSource(
  graph: MirrorGraph,
  mirrorId: string,
): { line: Line; owner: string | null } | null {
  const edge = graph.analysis.incoming.get(mirrorId)?.get('line')?.[0];
  if (!edge) {
    const line = graph.nodes.get(mirrorId)?.ctx?.inputs.line as Line | undefined;
    return line ? { line, owner: null } : null;
  }
  const from = graph.analysis.nodes.get(edge.from.node);
  const line = graph.nodes.get(edge.from.node)?.outputs?.[edge.from.port] as Line | undefined;
  // Only a Line node has handles "a" and "b"; a constructed line (bisector…) has no free point.
  return from?.node.type === 'line' && line ? { line, owner: edge.from.node } : null;
}

/** The two points that define mirror `mirrorId`'s line, or null when it has no free handles. */
function linePoints(graph: MirrorGraph, mirrorId: string): [LinePoint, LinePoint] | null {
  const source = lineSource(graph, mirrorId);
  if (!source) return null;
  const { analysis } = graph;
  const holder = source.owner ?? mirrorId;
  const index = analysis.nodes.get(holder)?.index ?? 0;
  const point = (h: 'a' | 'b', i: number): LinePoint => {
    const wire = source.owner ? analysis.incoming.get(source.owner)?.get(h)?.[0] : undefined;
    const from = wire ? analysis.nodes.get(wire.from.node) : undefined;
    // A wired point is free when it comes from a Point node whose own x, y are not wired.
    const isPoint = from?.node.type === 'point';
    return {
      id: wire ? `${wire.from.node}:${wire.from.port}` : `${holder}:${h}`,
      at: source.line[h],
      free: !wire || (isPoint && (analysis.incoming.get(wire.from.node)?.size ?? 0) === 0),
      name:
        wire && isPoint
          ? nodeName(analysis.nodes, wire.from.node)
          : `end ${h} of ${nodeName(analysis.nodes, holder)}`,
      rank: from ? from.index : index + i / 2,
      via: source.owner ? { lineNode: source.owner, handle: h } : { mirror: mirrorId, handle: h },
    };
  };
  return [point('a', 0), point('b', 1)];
}

/** A coordinate as a teacher reads it: three decimals at most, no "-0". */
const coord = (x: number) => `${Number(x.toFixed(3)) + 0}`;
export const formatPoint = (p: Vec2) => `(${coord(p[0])}, ${coord(p[1])})`;
/** The triple as one says it: sorted, "(2, 3, 6)". */
export const formatTriple = (orders: readonly number[]) =>
  `(${[...orders].sort((a, b) => a - b).join(', ')})`;

/** The fix's data: one move per point; a mirror's own line gets both ends in one params patch. */
function fixOf(
  label: string,
  snap: TriangleSnap,
  points: ReadonlyMap<string, LinePoint>,
  graph: MirrorGraph,
): DiagnosticFix {
  const moves: { nodeId: string; handle: string; to: Vec2 }[] = [];
  const ownLines = new Map<string, Line>();
  for (const m of snap.moves) {
    const via = points.get(m.id)!.via;
    if ('lineNode' in via) moves.push({ nodeId: via.lineNode, handle: via.handle, to: m.to });
    else {
      const line = ownLines.get(via.mirror) ?? (graph.nodes.get(via.mirror)?.ctx?.inputs.line as Line);
      ownLines.set(via.mirror, { ...line, [via.handle]: m.to });
    }
  }
  const params = [...ownLines].map(([nodeId, line]) => ({ nodeId, params: { line } }));
  return { label, ...(moves.length > 0 ? { moves } : {}), ...(params.length > 0 ? { params } : {}) };
}

export interface TriangleFix {
  readonly fix: DiagnosticFix;
  readonly snap: TriangleSnap;
}

/**
 * The one-step fix for the triangle of line mirrors `mirrorIds`, or null when a line has no two
 * points to move or every way to snap it would move a point that is not free.
 */
export function triangleFix(
  graph: MirrorGraph,
  mirrorIds: readonly [string, string, string],
  tolerance: number,
): TriangleFix | null {
  const defs = mirrorIds.map((id) => linePoints(graph, id));
  if (defs.some((d) => d === null)) return null;
  const points = new Map<string, LinePoint>();
  for (const d of defs as [LinePoint, LinePoint][])
    for (const p of d) if (!points.has(p.id)) points.set(p.id, p);
  const ordered = [...points.values()].sort((a, b) => a.rank - b.rank);
  const lines = defs.map((d) => ({ points: [d![0].id, d![1].id] })) as unknown as [
    SnapLine,
    SnapLine,
    SnapLine,
  ];
  const snap = snapTriangle({ lines, points: ordered, tolerance });
  if (!snap || snap.moves.length === 0) return null;
  const moved = snap.moves.map((m) => `${points.get(m.id)!.name} to ${formatPoint(m.to)}`).join(', ');
  return { fix: fixOf(`Snap to ${formatTriple(snap.orders)}: moves ${moved}`, snap, points, graph), snap };
}
