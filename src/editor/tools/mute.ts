/**
 * Mute (bypass) from the editor: M, the toolbar's Mute button and the inspector's toggle all build
 * this one change. The selection is muted unless every selected node already is; then it is unmuted.
 */
import type { GraphDoc } from '../../../nodes/graph/document.ts';
import type { Change } from '../../state/changes.ts';

export function muteToggle(doc: GraphDoc, selection: ReadonlySet<string>): Change | null {
  const nodes = doc.nodes.filter((n) => selection.has(n.id));
  if (nodes.length === 0) return null;
  const muted = !nodes.every((n) => n.muted === true);
  return { type: 'set-muted', nodeIds: nodes.map((n) => n.id), muted };
}

/** Whether every selected node is muted (the toggle's pressed state). */
export const allMuted = (doc: GraphDoc, selection: ReadonlySet<string>): boolean => {
  const nodes = doc.nodes.filter((n) => selection.has(n.id));
  return nodes.length > 0 && nodes.every((n) => n.muted === true);
};
