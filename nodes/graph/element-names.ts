/**
 * Names of the IIS elements for people ("Explain this pixel", `kleinflow sample --trace`): the
 * node's label, else its type's label; a node that gives several elements (a kaleidoscope's three
 * mirrors) numbers them in graph order, and where two nodes would still share a name (four
 * unlabelled circle inversions) the node's id is added, so every element of a word is told apart:
 * "Triangle kaleidoscope 2 · Triangle kaleidoscope 1 · …", "Circle inversion “iABC”".
 */
import type { Analysis } from './analyze.ts';

const count = <T>(items: readonly T[]): Map<T, number> => {
  const n = new Map<T, number>();
  for (const x of items) n.set(x, (n.get(x) ?? 0) + 1);
  return n;
};

export function elementNames(
  elements: readonly { readonly nodeId: string }[],
  analysis: Pick<Analysis, 'nodes'>,
): string[] {
  const ids = [...new Set(elements.map((e) => e.nodeId))];
  const base = new Map(
    ids.map((id) => {
      const entry = analysis.nodes.get(id);
      return [id, entry?.node.label?.trim() || entry?.def?.label || id] as const;
    }),
  );
  const shared = count(ids.map((id) => base.get(id)));
  const perNode = count(elements.map((e) => e.nodeId));
  const seen = new Map<string, number>();
  return elements.map(({ nodeId }) => {
    const name = base.get(nodeId)!;
    const k = (seen.get(nodeId) ?? 0) + 1;
    seen.set(nodeId, k);
    const who = (shared.get(name) ?? 1) > 1 ? `${name} “${nodeId}”` : name;
    return (perNode.get(nodeId) ?? 1) > 1 ? `${who} ${k}` : who;
  });
}
