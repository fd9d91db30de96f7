/** The inspector's "Save to My groups" for a group node: kept in this browser, offered by the palette. */
import { useState } from 'react';
import type { GraphNode } from '../../../nodes/graph/document.ts';
import { saveMyGroup } from './my-groups.ts';

export function SaveGroup({ node }: { node: GraphNode }) {
  const [saved, setSaved] = useState<string | null>(null);
  const name = node.label?.trim() || node.id;
  if (!node.group) return null;
  const body = node.group;
  return (
    <p className="kf-inspector__doc">
      <button
        type="button"
        className="kf-button"
        title="Keep this group in this browser; the palette (Space) lists it under My groups"
        onClick={() => {
          try {
            saveMyGroup(name, body);
            setSaved(`Saved as “${name}” in My groups.`);
          } catch {
            setSaved('Could not save: this browser’s storage is full or blocked.');
          }
        }}
      >
        Save to My groups
      </button>{' '}
      <span role="status">{saved}</span>
    </p>
  );
}
