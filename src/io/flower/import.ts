/**
 * Flower → Kleinflow: reads a Flower graph (format.ts), maps every node (node-types.ts), rewires
 * the edges (mirrors pass their input through, as in Flower), adds a tile that colours like Flower
 * and a render node with every mirror wired in Flower's order (circles, then lines), and opens on
 * the region Flower showed. Whatever does not carry over is reported as a KF502 note, never dropped silently.
 */
import { type Diagnostic, diag } from '../../../nodes/core/diagnostics.ts';
import { inputSpec, outputSpec, ownEntry } from '../../../nodes/core/port-lookup.ts';
import { canConnect } from '../../../nodes/core/ports.ts';
import type { NodeRegistry } from '../../../nodes/core/registry.ts';
import {
  DOC_VERSION,
  FORMAT,
  type GraphDoc,
  type GraphEdge,
  type GraphNode,
  newDocumentView,
} from '../../../nodes/graph/document.ts';
import { evaluateGraph } from '../../../nodes/graph/evaluate.ts';
import { loadDocument } from '../../../nodes/graph/load.ts';
import { registry as defaultRegistry } from '../../../nodes/types/index.ts';
import { addOutput, addTime, GRAPH_SPREAD, mirrorOrder } from './added-nodes.ts';
import { type FlowerGraph, isFlowerDocument, note, readFlowerGraph } from './format.ts';
import type { MappedNode } from './mapping.ts';
import { FLOWER_NODE_TYPES } from './node-types.ts';
import { flowerView } from './view.ts';

export { FLOWER_RENDER } from './added-nodes.ts';

export { isFlowerDocument } from './format.ts';

export type FlowerImportResult =
  | { ok: true; doc: GraphDoc; notes: Diagnostic[] }
  | { ok: false; diagnostics: Diagnostic[] };

export function importFlower(json: unknown, registry: NodeRegistry = defaultRegistry): FlowerImportResult {
  if (!isFlowerDocument(json)) {
    return {
      ok: false,
      diagnostics: [
        diag(
          'importProblem',
          { path: '(document)' },
          'not a Flower graph (expected "nodes" with "name" and "sockets")',
        ),
      ],
    };
  }
  const graph = readFlowerGraph(json as Record<string, unknown>);
  const notes = [...graph.notes];
  const mapped = mapNodes(graph, registry, notes);
  const ids = assignIds(graph, mapped);
  const nodes: GraphNode[] = [];
  for (const fn of graph.nodes) {
    const m = mapped.get(fn.id);
    if (!m) continue;
    const position: [number, number] = [Math.round(fn.x * GRAPH_SPREAD), Math.round(fn.y * GRAPH_SPREAD)];
    nodes.push({ id: ids.get(fn.id)!, type: m.type, position, params: m.params });
  }
  const edges = wireEdges(graph, mapped, ids, registry, notes);
  addTime(graph, mapped, ids, nodes, edges);
  addOutput(graph, mapped, ids, nodes, edges, notes);
  // Flower nodes map to today's params: mark them current (absent means version 1), so that
  // loading below does not migrate them as if they were old.
  for (const n of nodes) {
    const version = registry.get(n.type)?.version ?? 1;
    if (version !== 1) n.version = version;
  }

  const doc: GraphDoc = {
    format: FORMAT,
    version: DOC_VERSION,
    meta: {
      title: graph.name ?? 'Flower graph',
      description: `Imported from a Flower graph (${graph.nodes.length} nodes, ${graph.links.length} edges).`,
    },
    nodes,
    edges,
    view: newDocumentView(),
  };
  const view = flowerView(evaluateGraph(doc, registry).scene.overlays);
  doc.view = { center: [view.center[0], view.center[1]], scale: view.scale };
  const checked = loadDocument(doc, registry);
  if (!checked.ok) return checked;
  return { ok: true, doc: checked.doc, notes };
}

function mapNodes(graph: FlowerGraph, registry: NodeRegistry, notes: Diagnostic[]): Map<string, MappedNode> {
  const wired = new Map<string, Set<number>>();
  const consumers = new Map<string, string[]>();
  const nameOf = new Map(graph.nodes.map((n) => [n.id, n.name]));
  for (const l of graph.links) {
    const set = wired.get(l.to) ?? new Set<number>();
    set.add(l.toInput);
    wired.set(l.to, set);
    consumers.set(l.from, [...(consumers.get(l.from) ?? []), nameOf.get(l.to) ?? '']);
  }
  const mapped = new Map<string, MappedNode>();
  for (const node of graph.nodes) {
    const path = `nodes[${node.index}]`;
    const map = ownEntry(FLOWER_NODE_TYPES, node.name);
    if (!map) {
      notes.push(note(path, `unknown Flower node type "${node.name}" ("${node.id}"); skipped`));
      continue;
    }
    const m = map(node, {
      registry,
      wired: wired.get(node.id) ?? new Set(),
      consumers: consumers.get(node.id) ?? [],
    });
    if ('skip' in m) {
      if (m.skip !== null) notes.push(note(path, m.skip));
      continue;
    }
    for (const text of m.notes) notes.push(note(path, text));
    mapped.set(node.id, m);
  }
  return mapped;
}

/**
 * Readable ids: P1, L1, C1, … for construction nodes and mirror-01, mirror-02, … for mirrors in
 * Flower's order. Evaluation runs nodes in dependency order with ties broken by id, and the render
 * tests its elements in that order; every upper-case id sorts before "mirror-", so the mirrors
 * keep exactly this order.
 */
function assignIds(graph: FlowerGraph, mapped: ReadonlyMap<string, MappedNode>): Map<string, string> {
  const ids = new Map<string, string>();
  const counters = new Map<string, number>();
  for (const fn of graph.nodes) {
    const m = mapped.get(fn.id);
    if (!m || m.mirror) continue;
    const n = (counters.get(m.prefix) ?? 0) + 1;
    counters.set(m.prefix, n);
    ids.set(fn.id, `${m.prefix}${n}`);
  }
  const mirrors = mirrorOrder(graph, mapped);
  const width = String(mirrors.length).length;
  mirrors.forEach((fn, i) => {
    ids.set(fn.id, `mirror-${String(i + 1).padStart(Math.max(2, width), '0')}`);
  });
  return ids;
}

function wireEdges(
  graph: FlowerGraph,
  mapped: ReadonlyMap<string, MappedNode>,
  ids: ReadonlyMap<string, string>,
  registry: NodeRegistry,
  notes: Diagnostic[],
): GraphEdge[] {
  const typeOfId = new Map([...mapped].map(([flowerId, m]) => [ids.get(flowerId)!, m.type]));
  const into = new Map(graph.links.map((l) => [`${l.to}:${l.toInput}`, l]));
  /** The Kleinflow port that carries Flower output `ordinal` of `nodeId` (through pass-through mirrors). */
  const source = (nodeId: string, ordinal: number, depth = 0): { node: string; port: string } | null => {
    const out = mapped.get(nodeId)?.outputs[ordinal];
    if (!out || depth > graph.nodes.length) return null;
    if ('port' in out) return { node: ids.get(nodeId)!, port: out.port };
    const upstream = into.get(`${nodeId}:${out.passthroughInput}`);
    return upstream ? source(upstream.from, upstream.fromOutput, depth + 1) : null;
  };
  const edges: GraphEdge[] = [];
  for (const link of graph.links) {
    const target = mapped.get(link.to);
    const from = source(link.from, link.fromOutput);
    if (!target || !from) continue; // an end was skipped: its own note explains it
    const port = target.inputs[link.toInput];
    if (!port) {
      notes.push(
        note(
          `edges[${link.index}]`,
          `input ${link.toInput + 1} of Flower node "${link.to}" has no Kleinflow twin; edge skipped`,
        ),
      );
      continue;
    }
    const out = outputSpec(registry.get(typeOfId.get(from.node)!), from.port)?.type;
    const inp = inputSpec(registry.get(target.type), port)?.type;
    if (!out || !inp || !canConnect(out, inp)) {
      notes.push(
        note(
          `edges[${link.index}]`,
          `a ${out ?? '?'} cannot feed the ${inp ?? '?'} input "${port}" in Kleinflow; edge skipped`,
        ),
      );
      continue;
    }
    edges.push({ id: `e${edges.length + 1}`, from, to: { node: ids.get(link.to)!, port } });
  }
  return edges;
}
