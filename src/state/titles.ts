/**
 * Distinct default titles for new nodes, so that people — and the messages that name nodes by
 * title (nodes/graph/node-names.ts) — can tell three Line reflections apart: the first of a type
 * keeps the type's name (no label stored, as before), the next get "Line reflection 2",
 * "Line reflection 3"… (the smallest number free). A pasted or duplicated node whose title is
 * taken gets the next free number of its title's stem ("A" → "A 2", "Point 2" → "Point 3").
 */
import type { NodeRegistry } from '../../nodes/core/registry.ts';
import type { GraphNode } from '../../nodes/graph/document.ts';
import { nodeTitle } from '../../nodes/graph/node-names.ts';

type Titled = Pick<GraphNode, 'type' | 'label'>;

/** "Line reflection 2" → "Line reflection"; a title without a number is its own stem. */
export const stemOf = (title: string) => title.replace(/ \d+$/, '');

/**
 * A generator of labels for nodes added to `nodes` (and to earlier calls' nodes): undefined when
 * the node's own title is still free (it stays as it is), else the free title to store.
 */
export function titleAllocator(
  nodes: readonly Titled[],
  registry: NodeRegistry,
): (node: Titled) => string | undefined {
  const titleOf = (n: Titled) => nodeTitle(n, registry.get(n.type)?.label);
  const used = new Set(nodes.map(titleOf));
  return (node) => {
    const title = titleOf(node);
    if (!used.has(title)) {
      used.add(title);
      return node.label;
    }
    const stem = stemOf(title);
    let k = 2;
    while (used.has(`${stem} ${k}`)) k++;
    used.add(`${stem} ${k}`);
    return `${stem} ${k}`;
  };
}

/** `node` with the label the allocator gives it (none when it keeps its type's name). */
export function withTitle<T extends Titled>(node: T, allocate: (node: Titled) => string | undefined): T {
  const label = allocate(node);
  if (label === undefined) {
    const { label: _dropped, ...rest } = node;
    return rest as T;
  }
  return { ...node, label };
}
