/** Group (Ctrl+G) and ungroup (Ctrl+Shift+G) of the selection, as one change each. */
import type { GraphDoc } from '../../../nodes/graph/document.ts';
import type { Change } from '../../state/changes.ts';
import { idAllocator } from '../../state/ids.ts';

export function groupSelection(
  doc: GraphDoc,
  selection: ReadonlySet<string>,
): Extract<Change, { type: 'group' }> | null {
  const ids = doc.nodes.filter((n) => selection.has(n.id)).map((n) => n.id);
  if (ids.length === 0) return null;
  return { type: 'group', nodeIds: ids, groupId: idAllocator(doc)('group') };
}

/** Every selected group ungrouped (one step); null when no group is selected. */
export function ungroupSelection(doc: GraphDoc, selection: ReadonlySet<string>): Change | null {
  const groups = doc.nodes.filter((n) => selection.has(n.id) && n.group);
  if (groups.length === 0) return null;
  return { type: 'batch', changes: groups.map((g) => ({ type: 'ungroup', nodeId: g.id }) as const) };
}
