/**
 * Copy/paste of nodes as JSON `{ "format": "kleinflow-clipboard", nodes, edges }`: only edges
 * between copied nodes travel; a paste gets fresh ids and lands offset from the originals.
 * Pasted nodes are migrated like a loaded document's (they may come from an older Kleinflow in
 * another tab), so the document stays current.
 */
import { z } from 'zod';
import type { NodeRegistry } from '../../nodes/core/registry.ts';
import {
  edgeSchema,
  type GraphDoc,
  type GraphEdge,
  type GraphNode,
  nodeSchema,
} from '../../nodes/graph/document.ts';
import { migrateNodes } from '../../nodes/graph/migrate.ts';
import { registry as appRegistry } from '../../nodes/types/index.ts';
import { idAllocator } from './ids.ts';
import { titleAllocator, withTitle } from './titles.ts';

export const CLIPBOARD_FORMAT = 'kleinflow-clipboard';

const clipboardSchema = z.object({
  format: z.literal(CLIPBOARD_FORMAT),
  nodes: z.array(nodeSchema),
  edges: z.array(edgeSchema),
});

export type ClipboardData = z.infer<typeof clipboardSchema>;

/** The clipboard content for these nodes (edges only between them), or null when none are given. */
export function copyNodes(doc: GraphDoc, nodeIds: Iterable<string>): ClipboardData | null {
  const ids = new Set(nodeIds);
  const nodes = doc.nodes.filter((n) => ids.has(n.id));
  if (nodes.length === 0) return null;
  const edges = doc.edges.filter((e) => ids.has(e.from.node) && ids.has(e.to.node));
  return { format: CLIPBOARD_FORMAT, nodes, edges };
}

export const serializeClipboard = (data: ClipboardData): string => JSON.stringify(data);

/** Reads clipboard text, its nodes migrated to `registry`'s types; null when it is not Kleinflow nodes. */
export function parseClipboard(text: string, registry: NodeRegistry = appRegistry): ClipboardData | null {
  let value: unknown;
  try {
    value = JSON.parse(text);
  } catch {
    return null;
  }
  const parsed = clipboardSchema.safeParse(value);
  return parsed.success ? { ...parsed.data, nodes: migrateNodes(parsed.data.nodes, registry) } : null;
}

/**
 * New nodes/edges for pasting `data` into `doc`: fresh ids and titles, positions shifted so the group's
 * top-left corner lands at `at` (or `offset` from the originals when `at` is absent).
 */
export function preparePaste(
  doc: GraphDoc,
  data: ClipboardData,
  at?: readonly [number, number],
  offset: readonly [number, number] = [40, 40],
  registry: NodeRegistry = appRegistry,
): { nodes: GraphNode[]; edges: GraphEdge[] } {
  const next = idAllocator(doc);
  // A pasted node whose title is taken gets a free one, so copies are told apart too.
  const title = titleAllocator(doc.nodes, registry);
  const ids = new Map<string, string>();
  const minX = Math.min(...data.nodes.map((n) => n.position[0]));
  const minY = Math.min(...data.nodes.map((n) => n.position[1]));
  const [dx, dy] = at ? [at[0] - minX, at[1] - minY] : offset;
  const nodes = data.nodes
    .filter((n) => !ids.has(n.id))
    .map((n) => {
      const id = next(n.type);
      ids.set(n.id, id);
      const position: [number, number] = [n.position[0] + dx, n.position[1] + dy];
      return withTitle({ ...n, id, position }, title);
    });
  const edges = data.edges
    .filter((e) => ids.has(e.from.node) && ids.has(e.to.node))
    .map((e) => ({
      id: next('e'),
      from: { node: ids.get(e.from.node)!, port: e.from.port },
      to: { node: ids.get(e.to.node)!, port: e.to.port },
    }));
  return { nodes, edges };
}
