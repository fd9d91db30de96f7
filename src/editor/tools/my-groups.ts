/**
 * "My groups": groups saved in this browser (localStorage) to insert again from the palette.
 * What is read back is validated like a document's group (nodes/graph/document.ts): a damaged
 * entry is skipped, never trusted.
 */
import { z } from 'zod';
import {
  type GraphDoc,
  type GraphNode,
  type GroupBody,
  groupBodySchema,
} from '../../../nodes/graph/document.ts';
import { GROUP_TYPE } from '../../../nodes/graph/group-def.ts';
import type { Change } from '../../state/changes.ts';
import { idAllocator } from '../../state/ids.ts';
import { gridPosition } from '../new-node.ts';

export const MY_GROUPS_KEY = 'kleinflow.myGroups';
/** Enough for a personal library; each entry is a whole subgraph. */
const MAX_SAVED = 100;

const savedSchema = z.object({ name: z.string().min(1).max(200), body: groupBodySchema });
export type SavedGroup = z.infer<typeof savedSchema>;

export function readMyGroups(storage: Pick<Storage, 'getItem'> = localStorage): SavedGroup[] {
  let raw: unknown;
  try {
    raw = JSON.parse(storage.getItem(MY_GROUPS_KEY) ?? '[]');
  } catch {
    return [];
  }
  if (!Array.isArray(raw)) return [];
  return raw.flatMap((entry) => {
    const parsed = savedSchema.safeParse(entry);
    return parsed.success ? [parsed.data] : [];
  });
}

/** Saves a group under its name (replacing one of the same name); returns the new list. */
export function saveMyGroup(
  name: string,
  body: GroupBody,
  storage: Pick<Storage, 'getItem' | 'setItem'> = localStorage,
): SavedGroup[] {
  const list = [{ name, body }, ...readMyGroups(storage).filter((g) => g.name !== name)].slice(0, MAX_SAVED);
  storage.setItem(MY_GROUPS_KEY, JSON.stringify(list));
  return list;
}

/** The change inserting a saved group at a graph position (one undo step) and the new node's id. */
export function insertMyGroup(doc: GraphDoc, saved: SavedGroup, at: { x: number; y: number }) {
  const node: GraphNode = {
    id: idAllocator(doc)('group'),
    type: GROUP_TYPE,
    position: gridPosition(at.x, at.y),
    params: {},
    label: saved.name,
    group: saved.body,
  };
  const change: Change = { type: 'add-node', node };
  return { change, nodeId: node.id };
}
