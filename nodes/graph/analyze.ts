/**
 * Structural analysis of a valid document against a registry: duplicate ids, unknown node types,
 * dangling edges, unknown ports, port-type mismatches, several edges into a single input, self
 * edges and cycles. Bad edges are dropped from evaluation (and reported); nothing else is touched.
 */
import type { NodeDef } from '../core/define-node.ts';
import { type Diagnostic, diag } from '../core/diagnostics.ts';
import { inputSpec, outputSpec } from '../core/port-lookup.ts';
import { canConnect, PORT_TYPE_INFO } from '../core/ports.ts';
import type { NodeRegistry } from '../core/registry.ts';
import type { GraphDoc, GraphEdge, GraphNode } from './document.ts';
import { topologicalOrder } from './topo.ts';

export interface Analysis {
  /** Node by id (first occurrence wins on duplicates). */
  readonly nodes: ReadonlyMap<string, { node: GraphNode; index: number; def: NodeDef | undefined }>;
  /** Edges that passed every check, by target node, then by target port (document order). */
  readonly incoming: ReadonlyMap<string, ReadonlyMap<string, readonly GraphEdge[]>>;
  readonly order: readonly string[];
  readonly blocked: ReadonlySet<string>;
  readonly diagnostics: readonly Diagnostic[];
}

export function analyzeGraph(doc: GraphDoc, registry: NodeRegistry): Analysis {
  const diagnostics: Diagnostic[] = [];
  const nodes = new Map<string, { node: GraphNode; index: number; def: NodeDef | undefined }>();
  doc.nodes.forEach((node, index) => {
    const path = `nodes[${index}]`;
    const first = nodes.get(node.id);
    if (first) {
      const where = { path: `${path}.id`, nodeId: node.id };
      diagnostics.push(diag('duplicateNodeId', where, node.id, `nodes[${first.index}]`));
      return;
    }
    const def = registry.get(node.type);
    if (!def) diagnostics.push(diag('unknownNodeType', { path: `${path}.type`, nodeId: node.id }, node.type));
    nodes.set(node.id, { node, index, def });
  });

  const edgeIds = new Set<string>();
  const good: GraphEdge[] = [];
  doc.edges.forEach((edge, i) => {
    const path = `edges[${i}]`;
    if (edgeIds.has(edge.id)) {
      diagnostics.push(diag('duplicateEdgeId', { path: `${path}.id` }, edge.id));
      return;
    }
    edgeIds.add(edge.id);
    const problem = checkEdge(edge, path, nodes);
    if (problem) diagnostics.push(problem);
    else if (problem === null) good.push(edge);
  });

  const incoming = new Map<string, Map<string, GraphEdge[]>>();
  for (const edge of good) {
    const byPort = incoming.get(edge.to.node) ?? new Map<string, GraphEdge[]>();
    incoming.set(edge.to.node, byPort);
    const list = byPort.get(edge.to.port) ?? [];
    byPort.set(edge.to.port, list);
    list.push(edge);
  }
  for (const [nodeId, byPort] of incoming) {
    const { def } = nodes.get(nodeId)!;
    for (const [port, list] of byPort) {
      if (list.length > 1 && !PORT_TYPE_INFO[inputSpec(def, port)!.type].many) {
        diagnostics.push(
          diag('multipleEdges', { nodeId, port, path: `edges[${doc.edges.indexOf(list[1])}]` }, port),
        );
        byPort.set(port, [list[0]]);
      }
    }
  }

  const topo = topologicalOrder(
    [...nodes.keys()],
    [...incoming.values()]
      .flatMap((m) => [...m.values()].flat())
      .map((e) => ({ from: e.from.node, to: e.to.node })),
  );
  for (const cycle of topo.cycles) {
    const text = cycle.join(' → ');
    for (const id of new Set(cycle))
      diagnostics.push(diag('cycle', { nodeId: id, path: `nodes[${nodes.get(id)!.index}]` }, text));
  }
  return { nodes, incoming, order: topo.order, blocked: topo.blocked, diagnostics };
}

/**
 * An edge's problem, null when it is usable, or undefined when it leads into a placeholder node
 * (kept in the document, unused by evaluation, not reported twice).
 */
function checkEdge(
  edge: GraphEdge,
  path: string,
  nodes: ReadonlyMap<string, { node: GraphNode; def: NodeDef | undefined }>,
): Diagnostic | null | undefined {
  const src = nodes.get(edge.from.node);
  const dst = nodes.get(edge.to.node);
  if (!src) return diag('danglingEdge', { path: `${path}.from.node` }, 'source', edge.from.node);
  if (!dst) return diag('danglingEdge', { path: `${path}.to.node` }, 'target', edge.to.node);
  if (edge.from.node === edge.to.node) return diag('selfEdge', { path, nodeId: edge.to.node }, edge.to.node);
  if (!dst.def) return undefined;
  const out = outputSpec(src.def, edge.from.port);
  const inp = inputSpec(dst.def, edge.to.port);
  if (src.def && !out)
    return diag(
      'unknownPort',
      { path: `${path}.from.port`, nodeId: src.node.id },
      'source',
      edge.from.port,
      src.node.id,
    );
  if (!inp)
    return diag(
      'unknownPort',
      { path: `${path}.to.port`, nodeId: dst.node.id },
      'target',
      edge.to.port,
      dst.node.id,
    );
  // From a placeholder the edge is kept (its output type is unknown): the target then reports the
  // missing value instead of silently falling back to its inline default.
  if (!out) return null;
  if (!canConnect(out.type, inp.type)) {
    return diag('typeMismatch', { path, nodeId: dst.node.id, port: edge.to.port }, out.type, inp.type);
  }
  return null;
}
