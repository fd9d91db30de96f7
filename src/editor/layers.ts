/**
 * The layered ("Sugiyama-style") placement Tidy uses: which column each node goes in and the order
 * within each column, so a graph reads left to right from its sources to its Render node. Pure.
 *
 * Columns: the longest path from a source (cycles cut); then every node that feeds something moves
 * right until it sits just before the first node it feeds, so a wire spans one column where it can
 * (a colouring node wired only into Render sits beside Render, not far left with a long wire);
 * output nodes (no outputs: Render) go last, alone — the picture's node on the right.
 * Order: by the mean row of the nodes each is wired to, swept right then left (the barycentre
 * heuristic), which untangles most crossing wires; ties keep the current top-to-bottom order.
 */
import type { GraphDoc, GraphNode } from '../../nodes/graph/document.ts';

export interface Layers {
  /** Column of each node, from 0 on the left. */
  readonly column: ReadonlyMap<string, number>;
  /** The columns left to right, each top to bottom. */
  readonly columns: readonly (readonly GraphNode[])[];
}

const SWEEPS = 3;

export function layers(doc: GraphDoc, isOutput: (node: GraphNode) => boolean): Layers {
  const ids = new Set(doc.nodes.map((n) => n.id));
  const wires = doc.edges
    .map((e) => [e.from.node, e.to.node] as const)
    .filter(([a, b]) => ids.has(a) && ids.has(b) && a !== b);
  const depth = longestPaths(doc, wires);
  // Outputs last, alone in their column.
  const outputs = new Set(doc.nodes.filter(isOutput).map((n) => n.id));
  const inner = doc.nodes.filter((n) => !outputs.has(n.id)).map((n) => depth.get(n.id)!);
  const last = inner.length > 0 ? Math.max(...inner) + 1 : 0;
  for (const id of outputs) depth.set(id, last);
  pullRight(doc, wires, depth, outputs);
  const byColumn = new Map<number, GraphNode[]>();
  for (const n of doc.nodes) byColumn.set(depth.get(n.id)!, [...(byColumn.get(depth.get(n.id)!) ?? []), n]);
  const columns = [...byColumn]
    .sort((a, b) => a[0] - b[0])
    .map(([, ns]) => [...ns].sort((a, b) => a.position[1] - b.position[1] || (a.id < b.id ? -1 : 1)));
  // Renumber: a column emptied by the moves leaves no gap.
  const column = new Map<string, number>();
  columns.forEach((ns, i) => {
    for (const n of ns) column.set(n.id, i);
  });
  return { column, columns: untangle(columns, wires, column) };
}

/** Longest-path layering by relaxation; at most |nodes| rounds, so a cycle cannot loop forever. */
function longestPaths(doc: GraphDoc, wires: readonly (readonly [string, string])[]): Map<string, number> {
  const depth = new Map<string, number>(doc.nodes.map((n) => [n.id, 0]));
  for (let round = 0; round < doc.nodes.length; round++) {
    let changed = false;
    for (const [a, b] of wires) {
      const d = depth.get(a)! + 1;
      if (d > depth.get(b)! && d < doc.nodes.length) {
        depth.set(b, d);
        changed = true;
      }
    }
    if (!changed) break;
  }
  return depth;
}

/** Each node that feeds something moves right to just before the leftmost node it feeds. */
function pullRight(
  doc: GraphDoc,
  wires: readonly (readonly [string, string])[],
  depth: Map<string, number>,
  fixed: ReadonlySet<string>,
): void {
  const order = [...doc.nodes]
    .filter((n) => !fixed.has(n.id))
    .sort((a, b) => depth.get(b.id)! - depth.get(a.id)!);
  for (const n of order) {
    const fed = wires.filter(([a]) => a === n.id).map(([, b]) => depth.get(b)!);
    if (fed.length === 0) continue;
    const to = Math.min(...fed) - 1;
    if (to > depth.get(n.id)!) depth.set(n.id, to);
  }
}

/** Barycentre sweeps: each column ordered by the mean row of its neighbours in the other columns. */
function untangle(
  start: readonly (readonly GraphNode[])[],
  wires: readonly (readonly [string, string])[],
  column: ReadonlyMap<string, number>,
): GraphNode[][] {
  const columns = start.map((c) => [...c]);
  const row = new Map<string, number>();
  const number = () => {
    for (const c of columns) for (const [i, n] of c.entries()) row.set(n.id, i);
  };
  number();
  const sortBy = (c: GraphNode[], neighbours: (id: string) => string[]) => {
    const key = new Map(
      c.map((n) => {
        const ns = neighbours(n.id);
        return [n.id, ns.length ? ns.reduce((s, m) => s + row.get(m)!, 0) / ns.length : row.get(n.id)!];
      }),
    );
    c.sort((a, b) => key.get(a.id)! - key.get(b.id)! || row.get(a.id)! - row.get(b.id)!);
    for (const [i, n] of c.entries()) row.set(n.id, i);
  };
  const left = (id: string) =>
    wires.filter(([a, b]) => b === id && column.get(a)! < column.get(id)!).map(([a]) => a);
  const right = (id: string) =>
    wires.filter(([a, b]) => a === id && column.get(b)! > column.get(id)!).map(([, b]) => b);
  for (let s = 0; s < SWEEPS; s++) {
    for (let i = 1; i < columns.length; i++) sortBy(columns[i], left);
    for (let i = columns.length - 2; i >= 0; i--) sortBy(columns[i], right);
  }
  return columns;
}
