/**
 * Flattening groups (docs/architecture.md "Groups"): before analysis and evaluation every group
 * node is replaced by its inner nodes and edges, its outer wires reconnected to the inner ports
 * they stand for — one flat graph, so one shader and no cost at run time. An inner node keeps its
 * id when no other node has it (so grouping changes neither the topological order nor the Scene),
 * else it becomes "<group id>/<inner id>". A muted group mutes every node inside it.
 */
import type { GraphDoc, GraphEdge, GraphNode, PortRef } from './document.ts';

export interface Flattened {
  readonly doc: GraphDoc;
  /** For every node that came out of a group: its path (group ids from the top, then its own id). */
  readonly origin: ReadonlyMap<string, readonly string[]>;
  /**
   * For every flattened edge whose id is not the document's top-level edge of that id: the edge it
   * stands for (group ids from the top, then its id in the innermost group) — so a message about
   * a wire says where the wire is in the document.
   */
  readonly edgeOrigin: ReadonlyMap<string, readonly string[]>;
}

export const hasGroups = (doc: Pick<GraphDoc, 'nodes'>): boolean => doc.nodes.some((n) => n.group);

export function flattenGroups(doc: GraphDoc): Flattened {
  const origin = new Map<string, readonly string[]>();
  const edgeOrigin = new Map<string, readonly string[]>();
  let nodes: readonly GraphNode[] = doc.nodes;
  let edges: readonly GraphEdge[] = doc.edges;
  // One level per pass; the document's depth limit (LIMITS.maxJsonDepth) bounds the passes.
  while (nodes.some((n) => n.group))
    ({ nodes, edges } = expandOneLevel(nodes, edges, { nodes: origin, edges: edgeOrigin }));
  return { doc: { ...doc, nodes: [...nodes], edges: [...edges] }, origin, edgeOrigin };
}

interface Origins {
  readonly nodes: Map<string, readonly string[]>;
  readonly edges: Map<string, readonly string[]>;
}

function expandOneLevel(
  nodes: readonly GraphNode[],
  edges: readonly GraphEdge[],
  origins: Origins,
): { nodes: GraphNode[]; edges: GraphEdge[] } {
  const origin = origins.nodes;
  const used = new Set([...nodes.map((n) => n.id), ...edges.map((e) => e.id)]);
  const fresh = (wanted: string, scope: string) => {
    let id = used.has(wanted) ? `${scope}/${wanted}` : wanted;
    for (let i = 2; used.has(id); i++) id = `${scope}/${wanted}~${i}`;
    used.add(id);
    return id;
  };
  /** Per group id: inner id → flat id; exposed input → flat targets; exposed output → flat source. */
  const inputs = new Map<string, Map<string, PortRef[]>>();
  const outputs = new Map<string, Map<string, PortRef>>();
  const outNodes: GraphNode[] = [];
  const innerEdges: GraphEdge[] = [];
  for (const node of nodes) {
    const body = node.group;
    if (!body) {
      outNodes.push(node);
      continue;
    }
    const path = origin.get(node.id) ?? [node.id];
    const ids = new Map<string, string>();
    for (const inner of body.nodes) {
      const id = fresh(inner.id, node.id);
      ids.set(inner.id, id);
      origin.set(id, [...path, inner.id]);
      outNodes.push({ ...inner, id, ...(node.muted ? { muted: true } : {}) });
    }
    const ref = (r: PortRef): PortRef | null => {
      const id = ids.get(r.node);
      return id === undefined ? null : { node: id, port: r.port };
    };
    for (const e of body.edges) {
      const from = ref(e.from);
      const to = ref(e.to);
      if (!from || !to) continue;
      const id = fresh(e.id, node.id);
      origins.edges.set(id, [...path, e.id]);
      innerEdges.push({ ...e, id, from, to });
    }
    inputs.set(node.id, new Map(body.inputs.map((p) => [p.name, p.targets.flatMap((t) => ref(t) ?? [])])));
    const outs = new Map<string, PortRef>();
    for (const p of body.outputs) {
      const from = ref(p.from);
      if (from) outs.set(p.name, from);
    }
    outputs.set(node.id, outs);
  }
  const outEdges: GraphEdge[] = [];
  for (const e of edges) {
    const from = outputs.has(e.from.node) ? outputs.get(e.from.node)!.get(e.from.port) : e.from;
    const targets = inputs.has(e.to.node) ? (inputs.get(e.to.node)!.get(e.to.port) ?? []) : [e.to];
    // A wire to or from a port the group no longer exposes has nothing to stand for: it is dropped.
    if (!from) continue;
    targets.forEach((to, k) => {
      const id = k === 0 && targets.length === 1 ? e.id : fresh(`${e.id}>${k}`, e.id);
      // A fanned-out copy stands for the wire it was copied from.
      if (id !== e.id) origins.edges.set(id, origins.edges.get(e.id) ?? [e.id]);
      outEdges.push({ ...e, id, from, to });
    });
  }
  return { nodes: outNodes, edges: [...outEdges, ...innerEdges] };
}

/**
 * Where a grouped node lives in the document: `nodes[2].group.nodes[0]` for the path [g, c]; with
 * `kind` 'edges', where an edge does: `nodes[2].group.edges[1]` for the edge path [g, e].
 */
export function documentPath(
  doc: Pick<GraphDoc, 'nodes' | 'edges'>,
  path: readonly string[],
  kind: 'nodes' | 'edges' = 'nodes',
): string | null {
  let level: Pick<GraphDoc, 'nodes' | 'edges'> = doc;
  let out = '';
  for (const [i, id] of path.entries()) {
    const last = i === path.length - 1;
    const list = last && kind === 'edges' ? level.edges : level.nodes;
    const at = list.findIndex((n) => n.id === id);
    if (at < 0) return null;
    out += `${i === 0 ? '' : '.group.'}${last ? kind : 'nodes'}[${at}]`;
    if (!last) level = level.nodes[at].group ?? { nodes: [], edges: [] };
  }
  return out;
}

/** A node's path in the document: group ids from the top, then its own id (a top-level node: [id]). */
export type NodePath = readonly string[];

/** The document path of the node `flatId` names in the flattened graph. */
export const pathOf = (origin: ReadonlyMap<string, NodePath>, flatId: string): NodePath =>
  origin.get(flatId) ?? [flatId];

/** Whether `path` is `prefix` or lies inside it (a node inside the group at `prefix`). */
export const isUnder = (path: NodePath, prefix: NodePath): boolean =>
  prefix.length <= path.length && prefix.every((id, i) => path[i] === id);

/** The id at the group level `level` (a path of group ids) that `path` belongs to, or null when elsewhere. */
export const idAtLevel = (path: NodePath, level: NodePath): string | null =>
  path.length > level.length && isUnder(path, level) ? path[level.length] : null;
