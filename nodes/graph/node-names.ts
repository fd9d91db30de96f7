/**
 * How diagnostics name a node: by the title people see on it (its label, else its type's name),
 * never by the internal id, which the editor shows nowhere. New nodes get distinct titles
 * ("Line reflection 2", src/editor/node-titles.ts), but documents saved before that — or nodes
 * a person titled alike — can still share one; those get their place among the nodes with that
 * title in document order: “Line reflection” (2nd). Pure.
 */
import type { GraphNode } from './document.ts';

/** 1st, 2nd, 3rd, 4th, …, 11th, 12th, 13th, 21st. */
export function ordinal(k: number): string {
  const teen = k % 100 >= 11 && k % 100 <= 13;
  const suffix = teen ? 'th' : (['th', 'st', 'nd', 'rd'][k % 10] ?? 'th');
  return `${k}${suffix}`;
}

/** The title a node shows: its label, else its type's name (`typeLabel`), else its type. */
export function nodeTitle(node: Pick<GraphNode, 'label' | 'type'>, typeLabel: string | undefined): string {
  return node.label?.trim() || typeLabel || node.type;
}

/**
 * Every node's name for messages: “Title”, or “Title” (2nd) where several nodes show that title.
 * `typeLabel` gives a type's name (undefined for an unknown type).
 */
export function nodeNames<N extends Pick<GraphNode, 'id' | 'label' | 'type'>>(
  nodes: readonly N[],
  typeLabel: (node: N) => string | undefined,
  /** Single quotes where the name sits inside a message that may quote (group paths). */
  [open, close]: readonly [string, string] = ['“', '”'],
): Map<string, string> {
  const titles = nodes.map((n) => nodeTitle(n, typeLabel(n)));
  const total = new Map<string, number>();
  for (const t of titles) total.set(t, (total.get(t) ?? 0) + 1);
  const seen = new Map<string, number>();
  const names = new Map<string, string>();
  nodes.forEach((n, i) => {
    const t = titles[i];
    const k = (seen.get(t) ?? 0) + 1;
    seen.set(t, k);
    names.set(n.id, (total.get(t) ?? 1) > 1 ? `${open}${t}${close} (${ordinal(k)})` : `${open}${t}${close}`);
  });
  return names;
}

/** Every node of a document, inside groups too (ids are unique through all levels). */
export function everyNode(nodes: readonly GraphNode[]): GraphNode[] {
  return nodes.flatMap((n) => [n, ...(n.group ? everyNode(n.group.nodes) : [])]);
}

type NodeTable = ReadonlyMap<
  string,
  { readonly node: Pick<GraphNode, 'id' | 'label' | 'type'>; readonly def?: { readonly label: string } }
>;

/** Names per analysed graph, computed once (the mirror check runs on every drag frame). */
const cache = new WeakMap<NodeTable, Map<string, string>>();

/** A node's name for messages in an analysed graph (see nodeNames); the id only if it is unknown. */
export function nodeName(table: NodeTable, nodeId: string): string {
  let names = cache.get(table);
  if (!names) {
    const byId = new Map([...table.values()].map((e) => [e.node.id, e.def?.label]));
    names = nodeNames(
      [...table.values()].map((e) => e.node),
      (n) => byId.get(n.id),
    );
    cache.set(table, names);
  }
  return names.get(nodeId) ?? `node “${nodeId}”`;
}
