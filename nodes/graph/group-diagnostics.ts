/**
 * Diagnostics of a grouped document as the graph shows them at one level of groups
 * (docs/architecture.md "Groups"). Evaluation runs on the flattened graph, so a diagnostic names
 * its node by flattened id; at a level, one from inside a group goes on that group's node and its
 * message says where it comes from — “in group ‘Mirror pair’ → node ‘Circle 2’: …” — while a node
 * directly at the level keeps its own message.
 */
import type { Diagnostic } from '../core/diagnostics.ts';
import type { NodeRegistry } from '../core/registry.ts';
import type { GraphDoc } from './document.ts';
import { idAtLevel, type NodePath, pathOf } from './flatten.ts';
import { nodeDef } from './group-def.ts';
import { nodeNames } from './node-names.ts';

/** “in group ‘A’ → node ‘B’”: the way from the level's node `inner[0]` down to the node `inner.at(-1)`. */
function where(
  doc: Pick<GraphDoc, 'nodes'>,
  level: NodePath,
  inner: NodePath,
  registry: NodeRegistry,
): string {
  let nodes = doc.nodes;
  for (const id of level) nodes = nodes.find((n) => n.id === id)?.group?.nodes ?? [];
  const steps = inner.map((id, i) => {
    // Named by title, as the graph at that level shows them (node-names.ts), never by id.
    const names = nodeNames(nodes, (n) => nodeDef(registry, n)?.label, ['‘', '’']);
    nodes = nodes.find((n) => n.id === id)?.group?.nodes ?? [];
    const kind = i < inner.length - 1 ? 'group' : 'node';
    return `${kind} ${names.get(id) ?? `‘${id}’`}`;
  });
  return `in ${steps.join(' → ')}`;
}

/**
 * `d` as shown at the group level `level` (group ids from the top; [] the top level), or null when
 * it belongs to no node at or inside that level. Without a node, it belongs to the top level.
 */
export function diagnosticAtLevel(
  d: Diagnostic,
  doc: Pick<GraphDoc, 'nodes'>,
  origin: ReadonlyMap<string, NodePath>,
  level: NodePath,
  registry: NodeRegistry,
): Diagnostic | null {
  if (!d.nodeId) return level.length === 0 ? d : null;
  const path = pathOf(origin, d.nodeId);
  const local = idAtLevel(path, level);
  if (local === null) return null;
  const inner = path.slice(level.length);
  if (inner.length === 1) return local === d.nodeId ? d : { ...d, nodeId: local };
  // The group's ports have names of their own: the inner node's port would mark the wrong one.
  const { port: _inner, ...rest } = d;
  return { ...rest, nodeId: local, message: `${where(doc, level, inner, registry)}: ${d.message}` };
}
