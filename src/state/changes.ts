/**
 * Every edit of a document is a Change value; `applyChange` is the one pure function that turns
 * (doc, change) into the next doc. Undo/redo, autosave and the overlay's drags all go through it.
 * Changes never mutate: untouched nodes and edges keep their identity (cheap history snapshots).
 */

import { sameCamera3d } from '../../nodes/core/camera-3d.ts';
import { inputSpec, portSpec } from '../../nodes/core/port-lookup.ts';
import { PORT_TYPE_INFO } from '../../nodes/core/ports.ts';
import type { NodeRegistry } from '../../nodes/core/registry.ts';
import { sameView } from '../../nodes/core/view.ts';
import type { GraphDoc, GraphEdge, GraphFrame, GraphNode, PortRef } from '../../nodes/graph/document.ts';
import { nodeDef } from '../../nodes/graph/group-def.ts';
import { groupNodes, ungroupNode } from '../../nodes/graph/grouping.ts';
import { applyInGroup, routeIntoGroups } from './group-changes.ts';
import { idAllocator } from './ids.ts';

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
  /** The 3D view's camera (view state, like set-view); null goes back to the render-3d node's camera. */
  | { readonly type: 'set-camera-3d'; readonly camera: NonNullable<GraphDoc['camera3d']> | null }
  | { readonly type: 'set-meta'; readonly meta: GraphDoc['meta'] }
  /** Mutes (bypasses) or unmutes nodes (nodes/graph/mute.ts); `muted: false` removes the key. */
  | { readonly type: 'set-muted'; readonly nodeIds: readonly string[]; readonly muted: boolean }
  /** Adds a frame, or replaces the frame with its id. */
  | { readonly type: 'put-frame'; readonly frame: GraphFrame }
  | { readonly type: 'remove-frames'; readonly frameIds: readonly string[] }
  /** An edge's reroute points (empty removes them). */
  | {
      readonly type: 'set-via';
      readonly edgeId: string;
      readonly via: readonly (readonly [number, number])[];
    }
  /** Replaces the nodes `nodeIds` by one group node `groupId` (nodes/graph/grouping.ts). */
  | { readonly type: 'group'; readonly nodeIds: readonly string[]; readonly groupId: string }
  /** Replaces a group node by its nodes and wires. */
  | { readonly type: 'ungroup'; readonly nodeId: string }
  /** `change` applied inside a group: `path` names the group ids from the top (an edit while a group is open). */
  | { readonly type: 'in-group'; readonly path: readonly string[]; readonly change: Change }
  /** Several changes as one step (e.g. add a node and wire it). */
  | { readonly type: 'batch'; readonly changes: readonly Change[] };

const samePort = (a: PortRef, b: PortRef) => a.node === b.node && a.port === b.port;

/** Whether the input `to` takes many edges (unknown types/ports count as single). */
export function inputTakesMany(doc: GraphDoc, registry: NodeRegistry, to: PortRef): boolean {
  const node = doc.nodes.find((n) => n.id === to.node);
  const spec = node ? inputSpec(nodeDef(registry, node), to.port) : undefined;
  return spec ? PORT_TYPE_INFO[spec.type].many : false;
}

/** Whether the node `id` exists and (when its type is known) has the port `port` on `side`. */
function hasPort(doc: GraphDoc, registry: NodeRegistry, ref: PortRef, side: 'inputs' | 'outputs'): boolean {
  const node = doc.nodes.find((n) => n.id === ref.node);
  if (!node) return false;
  const def = nodeDef(registry, node);
  return !def || portSpec(def, side, ref.port) !== undefined; // an unknown type's ports are unknown: its wires are kept
}

/** `doc` with `f` applied to each node, or `doc` itself when `f` changed none (a no-op is no undo step). */
function mapNodes(doc: GraphDoc, f: (n: GraphNode) => GraphNode): GraphDoc {
  let changed = false;
  const nodes = doc.nodes.map((n) => {
    const next = f(n);
    if (next !== n) changed = true;
    return next;
  });
  return changed ? { ...doc, nodes } : doc;
}

/** `list` with `frame` replacing the frame with its id, or appended. */
function upsert(list: readonly GraphFrame[], frame: GraphFrame): GraphFrame[] {
  const at = list.findIndex((f) => f.id === frame.id);
  return at < 0 ? [...list, frame] : list.map((f, i) => (i === at ? frame : f));
}

/** `doc` with these frames; an empty list removes the key (a document without frames stays as it was). */
function withFrames(doc: GraphDoc, frames: GraphFrame[]): GraphDoc {
  const { frames: _old, ...rest } = doc;
  return frames.length > 0 ? { ...rest, frames } : rest;
}

const shallowEqual = (a: Readonly<Record<string, unknown>>, b: Readonly<Record<string, unknown>>) =>
  Object.keys(a).length === Object.keys(b).length &&
  Object.keys(a).every((k) => k in b && Object.is(a[k], b[k]));

/**
 * (doc, change) → next doc. `registry` decides which inputs take many edges. A change that changes
 * nothing (moving a node to where it is, removing ids that are not there, a wire to a missing node
 * or port) returns `doc` itself, so the store records no empty undo step.
 */
export function applyChange(doc: GraphDoc, change: Change, registry: NodeRegistry): GraphDoc {
  switch (change.type) {
    case 'add-node':
      if (doc.nodes.some((n) => n.id === change.node.id))
        throw new Error(`node id "${change.node.id}" exists`);
      return { ...doc, nodes: [...doc.nodes, change.node] };
    case 'remove': {
      const nodes = new Set(change.nodeIds);
      const edges = new Set(change.edgeIds ?? []);
      const keptNodes = doc.nodes.filter((n) => !nodes.has(n.id));
      const keptEdges = doc.edges.filter(
        (e) => !edges.has(e.id) && !nodes.has(e.from.node) && !nodes.has(e.to.node),
      );
      if (keptNodes.length === doc.nodes.length && keptEdges.length === doc.edges.length) return doc;
      return { ...doc, nodes: keptNodes, edges: keptEdges };
    }
    case 'move-nodes': {
      const to = new Map(change.moves.map((m) => [m.nodeId, m.position]));
      return mapNodes(doc, (n) => {
        const p = to.get(n.id);
        return p && (p[0] !== n.position[0] || p[1] !== n.position[1]) ? { ...n, position: p } : n;
      });
    }
    case 'set-params': {
      const routed = routeIntoGroups(doc, change.patches);
      if (routed) return applyChange(doc, routed, registry);
      const patches = new Map<string, Record<string, unknown>>();
      for (const p of change.patches) patches.set(p.nodeId, { ...patches.get(p.nodeId), ...p.params });
      return mapNodes(doc, (n) => {
        const patch = patches.get(n.id);
        if (!patch) return n;
        const params = { ...n.params, ...patch };
        for (const [k, v] of Object.entries(patch)) if (v === undefined) delete params[k];
        return shallowEqual(params, n.params) ? n : { ...n, params };
      });
    }
    case 'set-label': {
      const label = change.label.trim();
      return mapNodes(doc, (n) => {
        if (n.id !== change.nodeId || (n.label ?? '') === label) return n;
        const { label: _old, ...rest } = n;
        return label ? { ...rest, label } : rest;
      });
    }
    case 'connect': {
      const { edge } = change;
      if (!hasPort(doc, registry, edge.from, 'outputs') || !hasPort(doc, registry, edge.to, 'inputs'))
        return doc;
      if (doc.edges.some((e) => samePort(e.from, edge.from) && samePort(e.to, edge.to))) return doc; // already wired
      const many = inputTakesMany(doc, registry, edge.to);
      return { ...doc, edges: [...doc.edges.filter((e) => many || !samePort(e.to, edge.to)), edge] };
    }
    case 'paste':
      if (change.nodes.length === 0 && change.edges.length === 0) return doc;
      return { ...doc, nodes: [...doc.nodes, ...change.nodes], edges: [...doc.edges, ...change.edges] };
    case 'load-document':
      return change.doc;
    case 'set-view': {
      return sameView(change.view, doc.view) ? doc : { ...doc, view: change.view };
    }
    case 'set-camera-3d': {
      if (change.camera === null) {
        if (doc.camera3d === undefined) return doc;
        const { camera3d: _dropped, ...rest } = doc;
        return rest;
      }
      return doc.camera3d && sameCamera3d(change.camera, doc.camera3d)
        ? doc
        : { ...doc, camera3d: change.camera };
    }
    case 'set-meta':
      return shallowEqual(change.meta, doc.meta) ? doc : { ...doc, meta: change.meta };
    case 'set-muted': {
      const ids = new Set(change.nodeIds);
      return mapNodes(doc, (n) => {
        if (!ids.has(n.id) || (n.muted === true) === change.muted) return n;
        const { muted: _old, ...rest } = n;
        return change.muted ? { ...rest, muted: true } : rest;
      });
    }
    case 'put-frame': {
      const old = doc.frames?.find((f) => f.id === change.frame.id);
      if (old && JSON.stringify(old) === JSON.stringify(change.frame)) return doc;
      return withFrames(doc, upsert(doc.frames ?? [], change.frame));
    }
    case 'remove-frames': {
      const ids = new Set(change.frameIds);
      const kept = (doc.frames ?? []).filter((f) => !ids.has(f.id));
      return kept.length === (doc.frames ?? []).length ? doc : withFrames(doc, kept);
    }
    case 'set-via': {
      let changed = false;
      const edges = doc.edges.map((e) => {
        if (e.id !== change.edgeId) return e;
        const { via: old, ...rest } = e;
        if (JSON.stringify(old ?? []) === JSON.stringify(change.via)) return e;
        changed = true;
        return change.via.length > 0
          ? { ...rest, via: change.via.map(([x, y]) => [x, y] as [number, number]) }
          : rest;
      });
      return changed ? { ...doc, edges } : doc;
    }
    case 'group':
      return groupNodes(doc, change.nodeIds, change.groupId);
    case 'ungroup':
      return ungroupNode(doc, change.nodeId, idAllocator(doc));
    case 'in-group':
      return applyInGroup(doc, change.path, change.change, (d, c) => applyChange(d, c, registry));
    case 'batch':
      return change.changes.reduce((d, c) => applyChange(d, c, registry), doc);
  }
}
