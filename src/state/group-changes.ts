/**
 * Edits inside groups (docs/architecture.md "Groups"): a change applied to a group's subgraph as if
 * it were a document, and param patches addressed to nodes inside groups by their flattened id
 * (what the render's handle drags and the diagnostics' fixes name) routed to where they live.
 */
import type { GraphDoc, GroupBody } from '../../nodes/graph/document.ts';
import { flattenGroups, hasGroups } from '../../nodes/graph/flatten.ts';

// Structural types (not changes.ts's, which imports this file): they are assignable to its Change.
interface Patch {
  readonly nodeId: string;
  readonly params: Readonly<Record<string, unknown>>;
}
type SetParams = { readonly type: 'set-params'; readonly patches: readonly Patch[] };
type Routed =
  | SetParams
  | { readonly type: 'in-group'; readonly path: readonly string[]; readonly change: SetParams };

/** A group's body as a document: its nodes, edges and frames with the document's view and meta. */
function bodyDocument(doc: GraphDoc, body: GroupBody): GraphDoc {
  const { frames: _outer, ...rest } = doc;
  const inner = { ...rest, nodes: body.nodes, edges: body.edges };
  return body.frames ? { ...inner, frames: body.frames } : inner;
}

/** The subgraph of the group at `path` as a document (its own frames), or null. */
export function scopeDocument(doc: GraphDoc, path: readonly string[]): GraphDoc | null {
  let current: GraphDoc = doc;
  for (const id of path) {
    const body = current.nodes.find((n) => n.id === id)?.group;
    if (!body) return null;
    current = bodyDocument(current, body);
  }
  return current;
}

/** Exposed ports whose inner node is gone are dropped with the body (they stand for nothing). */
function pruneBody(body: GroupBody): GroupBody {
  const ids = new Set(body.nodes.map((n) => n.id));
  const inputs = body.inputs
    .map((p) => ({ ...p, targets: p.targets.filter((t) => ids.has(t.node)) }))
    .filter((p) => p.targets.length > 0);
  const outputs = body.outputs.filter((p) => ids.has(p.from.node));
  const same =
    inputs.length === body.inputs.length &&
    inputs.every((p, i) => p.targets.length === body.inputs[i].targets.length) &&
    outputs.length === body.outputs.length;
  return same ? body : { ...body, inputs, outputs };
}

/** `change` applied (by `apply`, changes.ts's applyChange) to the subgraph of the group at `path`. */
export function applyInGroup<C>(
  doc: GraphDoc,
  path: readonly string[],
  change: C,
  apply: (doc: GraphDoc, change: C) => GraphDoc,
): GraphDoc {
  const [head, ...rest] = path;
  if (head === undefined) return apply(doc, change);
  const at = doc.nodes.findIndex((n) => n.id === head);
  const group = doc.nodes[at];
  if (!group?.group) return doc;
  const inner = bodyDocument(doc, group.group);
  const next = applyInGroup(inner, rest, change, apply);
  if (next === inner) return doc;
  const { frames: _old, ...kept } = group.group;
  const frames = next.frames?.length ? { frames: next.frames } : {};
  const body = pruneBody({ ...kept, nodes: next.nodes, edges: next.edges, ...frames });
  const ports = new Set([...body.inputs, ...body.outputs].map((p) => p.name));
  const nodes = doc.nodes.map((n, i) => (i === at ? { ...group, group: body } : n));
  // Wires to ports the group no longer exposes go with them.
  const edges = doc.edges.filter(
    (e) =>
      !((e.to.node === head && !ports.has(e.to.port)) || (e.from.node === head && !ports.has(e.from.port))),
  );
  return { ...doc, nodes, edges: edges.length === doc.edges.length ? doc.edges : edges };
}

/**
 * Patches naming nodes that are not at the top level but inside groups (by flattened id) as one
 * batch of `in-group` changes; null when every patch names a top-level node (the usual case).
 */
export function routeIntoGroups(
  doc: GraphDoc,
  patches: readonly Patch[],
): { readonly type: 'batch'; readonly changes: readonly Routed[] } | null {
  if (!hasGroups(doc)) return null;
  const top = new Set(doc.nodes.map((n) => n.id));
  if (patches.every((p) => top.has(p.nodeId))) return null;
  const { origin } = flattenGroups(doc);
  const changes: Routed[] = [];
  for (const p of patches) {
    const path = origin.get(p.nodeId);
    if (top.has(p.nodeId)) {
      changes.push({ type: 'set-params', patches: [p] });
      continue;
    }
    if (!path) continue; // a node that is nowhere: nothing to patch (as at the top level)
    const inner: SetParams = { type: 'set-params', patches: [{ ...p, nodeId: path[path.length - 1] }] };
    changes.push({ type: 'in-group', path: path.slice(0, -1), change: inner });
  }
  return { type: 'batch', changes };
}
