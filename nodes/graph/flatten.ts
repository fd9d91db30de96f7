/**
 * Flattening groups (docs/architecture.md "Groups"): before analysis and evaluation every group
 * node is replaced by its inner nodes and edges, its outer wires reconnected to the inner ports
 * they stand for — one flat graph, so one shader and no cost at run time. An inner node keeps its
 * id when no other node has it (so grouping changes neither the topological order nor the Scene),
 * else it becomes "<group id>/<inner id>". A muted group mutes every node inside it.
 */
import { type Diagnostic, diag } from '../core/diagnostics.ts';
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
  /**
   * What flattening could not reconnect, with its place in the document: a group port naming an
   * inner node that is not there, a wire to or from a port a group does not have. (A wire inside a
   * group to a missing inner node stays in the flat graph, where analysis reports it like any other.)
   */
  readonly diagnostics: readonly Diagnostic[];
}

export const hasGroups = (doc: Pick<GraphDoc, 'nodes'>): boolean => doc.nodes.some((n) => n.group);

export function flattenGroups(doc: GraphDoc): Flattened {
  const origin = new Map<string, readonly string[]>();
  const edgeOrigin = new Map<string, readonly string[]>();
  const problems: Problem[] = [];
  const clashes = duplicateIds(doc.nodes, '');
  let nodes: readonly GraphNode[] = doc.nodes;
  let edges: readonly GraphEdge[] = doc.edges;
  // One level per pass; the document's depth limit (LIMITS.maxJsonDepth) bounds the passes.
  while (nodes.some((n) => n.group))
    ({ nodes, edges } = expandOneLevel(nodes, edges, { nodes: origin, edges: edgeOrigin, problems }));
  const diagnostics = problems.map(({ kind, path, rest, make }) => {
    const at = documentPath(doc, path, kind);
    return make(at === null ? undefined : `${at}${rest}`);
  });
  return {
    doc: { ...doc, nodes: [...nodes], edges: [...edges] },
    origin,
    edgeOrigin,
    diagnostics: [...clashes, ...diagnostics],
  };
}

/**
 * KF201 for two nodes of one id in one list where flattening would otherwise lose one silently:
 * inside a group (its wires could reach only one of them), or at the top where one of the two is a
 * group (a group is gone before analysis, which reports two plain top-level nodes itself). Ids in
 * different lists never collide: flattening scopes them ("<group id>/<inner id>").
 */
function duplicateIds(list: readonly GraphNode[], at: string): Diagnostic[] {
  const out: Diagnostic[] = [];
  const first = new Map<string, number>();
  list.forEach((node, i) => {
    const j = first.get(node.id);
    if (j === undefined) first.set(node.id, i);
    else if (at !== '' || node.group || list[j].group) {
      const where = { path: `${at}nodes[${i}].id`, nodeId: node.id };
      out.push(diag('duplicateNodeId', where, node.id, `${at}nodes[${j}]`));
    }
    if (node.group) out.push(...duplicateIds(node.group.nodes, `${at}nodes[${i}].group.`));
  });
  return out;
}

/** A problem found while expanding, placed in the document once flattening is done. */
interface Problem {
  /** The group node's path (kind 'nodes') or the wire's (kind 'edges'), ids from the top. */
  readonly kind: 'nodes' | 'edges';
  readonly path: readonly string[];
  /** The rest of the JSON path after the node's or wire's own, e.g. `.group.inputs[0].targets[1].node`. */
  readonly rest: string;
  readonly make: (path: string | undefined) => Diagnostic;
}

interface Origins {
  readonly nodes: Map<string, readonly string[]>;
  readonly edges: Map<string, readonly string[]>;
  readonly problems: Problem[];
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
  const outputs = new Map<string, Map<string, PortRef | null>>();
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
    /** A group port naming a missing inner node: reported on the group node, the port left unwired. */
    const missing = (rest: string, port: string, inner: string) =>
      origins.problems.push({
        kind: 'nodes',
        path,
        rest,
        make: (at) => diag('groupPortMissing', { path: at, nodeId: node.id }, port, inner),
      });
    const ghosts = new Map<string, string>();
    for (const e of body.edges) {
      // A wire to a missing inner node keeps that name (made unique), so analysis reports it.
      const end = (r: PortRef): PortRef => {
        const known = ref(r);
        if (known) return known;
        if (!ghosts.has(r.node)) ghosts.set(r.node, fresh(r.node, node.id));
        return { node: ghosts.get(r.node)!, port: r.port };
      };
      const id = fresh(e.id, node.id);
      origins.edges.set(id, [...path, e.id]);
      innerEdges.push({ ...e, id, from: end(e.from), to: end(e.to) });
    }
    const exposedInputs = body.inputs.map((p, i): [string, PortRef[]] => [
      p.name,
      p.targets.flatMap((t, k) => {
        const to = ref(t);
        if (!to) missing(`.group.inputs[${i}].targets[${k}].node`, p.name, t.node);
        return to ?? [];
      }),
    ]);
    inputs.set(node.id, new Map(exposedInputs));
    // Every exposed output, null where it names a missing inner node (reported just here).
    const outs = new Map<string, PortRef | null>();
    for (const [i, p] of body.outputs.entries()) {
      const from = ref(p.from);
      outs.set(p.name, from);
      if (!from) missing(`.group.outputs[${i}].from.node`, p.name, p.from.node);
    }
    outputs.set(node.id, outs);
  }
  /** A wire to or from a port its group does not expose: dropped, and said at the wire's port. */
  const unexposed = (e: GraphEdge, end: 'source' | 'target') => {
    const ref = end === 'source' ? e.from : e.to;
    origins.problems.push({
      kind: 'edges',
      path: origins.edges.get(e.id) ?? [e.id],
      rest: `.${end === 'source' ? 'from' : 'to'}.port`,
      make: (at) => diag('unknownPort', { path: at, nodeId: ref.node }, end, ref.port, ref.node),
    });
  };
  const outEdges: GraphEdge[] = [];
  for (const e of edges) {
    const groupOut = outputs.get(e.from.node);
    const groupIn = inputs.get(e.to.node);
    if (groupOut && !groupOut.has(e.from.port)) unexposed(e, 'source');
    if (groupIn && !groupIn.has(e.to.port)) unexposed(e, 'target');
    const from = groupOut ? groupOut.get(e.from.port) : e.from;
    const targets = groupIn ? (groupIn.get(e.to.port) ?? []) : [e.to];
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
