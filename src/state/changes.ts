/**
 * Every edit of a document is a Change value; `applyChange` is the one pure function that turns
 * (doc, change) into the next doc. Undo/redo, autosave and the overlay's drags all go through it.
 * Changes never mutate: untouched nodes and edges keep their identity (cheap history snapshots).
 */
import { PORT_TYPE_INFO } from '../../nodes/core/ports.ts';
import type { NodeRegistry } from '../../nodes/core/registry.ts';
import type { GraphDoc, GraphEdge, GraphNode, PortRef } from '../../nodes/graph/document.ts';

export interface ParamPatch {
  readonly nodeId: string;
  readonly params: Readonly<Record<string, unknown>>;
}

export type Change =
  | { readonly type: 'add-node'; readonly node: GraphNode }
  | { readonly type: 'remove'; readonly nodeIds: readonly string[]; readonly edgeIds?: readonly string[] }
  | { readonly type: 'move-nodes'; readonly moves: readonly { nodeId: string; position: [number, number] }[] }
  /** Merges the given keys into each node's params (a value of `undefined` removes the key). */
  | { readonly type: 'set-params'; readonly patches: readonly ParamPatch[] }
  | { readonly type: 'set-label'; readonly nodeId: string; readonly label: string }
  /** Adds an edge; a single (non-`many`) input first loses its existing edge. */
  | { readonly type: 'connect'; readonly edge: GraphEdge }
  | { readonly type: 'paste'; readonly nodes: readonly GraphNode[]; readonly edges: readonly GraphEdge[] }
  | { readonly type: 'load-document'; readonly doc: GraphDoc }
  | { readonly type: 'set-view'; readonly view: GraphDoc['view'] }
  | { readonly type: 'set-meta'; readonly meta: GraphDoc['meta'] }
  /** Several changes as one step (e.g. add a node and wire it). */
  | { readonly type: 'batch'; readonly changes: readonly Change[] };

const samePort = (a: PortRef, b: PortRef) => a.node === b.node && a.port === b.port;

/** Whether the input `to` takes many edges (unknown types/ports count as single). */
export function inputTakesMany(doc: GraphDoc, registry: NodeRegistry, to: PortRef): boolean {
  const node = doc.nodes.find((n) => n.id === to.node);
  const spec = node ? registry.get(node.type)?.inputs[to.port] : undefined;
  return spec ? PORT_TYPE_INFO[spec.type].many : false;
}

/** (doc, change) → next doc. `registry` decides which inputs take many edges. */
export function applyChange(doc: GraphDoc, change: Change, registry: NodeRegistry): GraphDoc {
  switch (change.type) {
    case 'add-node':
      if (doc.nodes.some((n) => n.id === change.node.id))
        throw new Error(`node id "${change.node.id}" exists`);
      return { ...doc, nodes: [...doc.nodes, change.node] };
    case 'remove': {
      const nodes = new Set(change.nodeIds);
      const edges = new Set(change.edgeIds ?? []);
      return {
        ...doc,
        nodes: doc.nodes.filter((n) => !nodes.has(n.id)),
        edges: doc.edges.filter((e) => !edges.has(e.id) && !nodes.has(e.from.node) && !nodes.has(e.to.node)),
      };
    }
    case 'move-nodes': {
      const to = new Map(change.moves.map((m) => [m.nodeId, m.position]));
      return { ...doc, nodes: doc.nodes.map((n) => (to.has(n.id) ? { ...n, position: to.get(n.id)! } : n)) };
    }
    case 'set-params': {
      const patches = new Map<string, Record<string, unknown>>();
      for (const p of change.patches) patches.set(p.nodeId, { ...patches.get(p.nodeId), ...p.params });
      return {
        ...doc,
        nodes: doc.nodes.map((n) => {
          const patch = patches.get(n.id);
          if (!patch) return n;
          const params = { ...n.params, ...patch };
          for (const [k, v] of Object.entries(patch)) if (v === undefined) delete params[k];
          return { ...n, params };
        }),
      };
    }
    case 'set-label':
      return {
        ...doc,
        nodes: doc.nodes.map((n) => {
          if (n.id !== change.nodeId) return n;
          const { label: _old, ...rest } = n;
          return change.label.trim() ? { ...rest, label: change.label.trim() } : rest;
        }),
      };
    case 'connect': {
      const { edge } = change;
      const many = inputTakesMany(doc, registry, edge.to);
      const kept = doc.edges.filter(
        (e) => !samePort(e.to, edge.to) || (many && !samePort(e.from, edge.from)),
      );
      if (many && kept.length < doc.edges.length) return doc; // the same wire already exists
      return { ...doc, edges: [...kept, edge] };
    }
    case 'paste':
      return { ...doc, nodes: [...doc.nodes, ...change.nodes], edges: [...doc.edges, ...change.edges] };
    case 'load-document':
      return change.doc;
    case 'set-view':
      return { ...doc, view: change.view };
    case 'set-meta':
      return { ...doc, meta: change.meta };
    case 'batch':
      return change.changes.reduce((d, c) => applyChange(d, c, registry), doc);
  }
}
