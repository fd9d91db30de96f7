/**
 * Toolbar buttons that act on the selected nodes: Mute (M), Frame, Group (Ctrl+G), Ungroup
 * (Ctrl+Shift+G). Each is one undo step.
 */
import { useEditorState, useStore } from '../../state/use-store.ts';
import { frameAround } from './frames.ts';
import { groupSelection, ungroupSelection } from './group-actions.ts';
import { allMuted, muteToggle } from './mute.ts';

export function SelectionTools() {
  const store = useStore();
  const doc = useEditorState((s) => s.doc);
  const selection = useEditorState((s) => s.selection);
  const some = doc.nodes.some((n) => selection.has(n.id));
  const muted = allMuted(doc, selection);
  const groups = doc.nodes.some((n) => selection.has(n.id) && n.group);
  const run = (label: string, make: () => ReturnType<typeof muteToggle>) => {
    const change = make();
    if (change) store.dispatch(change, label);
  };
  return (
    <>
      <button
        type="button"
        className={`kf-button${muted ? ' kf-button--active' : ''}`}
        aria-pressed={muted}
        disabled={!some}
        title="Mute the selected nodes: skipped, their elements leave the picture (M)"
        onClick={() => run(muted ? 'unmute' : 'mute', () => muteToggle(doc, selection))}
      >
        Mute
      </button>
      <button
        type="button"
        className="kf-button"
        disabled={!some}
        title="Put a titled frame behind the selected nodes; dragging the frame moves them"
        onClick={() => run('add frame', () => frameAround(doc, selection))}
      >
        Frame
      </button>
      <button
        type="button"
        className="kf-button"
        disabled={!some}
        title="Make the selected nodes one group node; wires crossing the selection become its ports (Ctrl+G)"
        onClick={() => {
          const change = groupSelection(doc, selection);
          run('group', () => change);
          if (change) store.setSelection([change.groupId]);
        }}
      >
        Group
      </button>
      <button
        type="button"
        className="kf-button"
        disabled={!groups}
        title="Put the selected groups' nodes back in the graph (Ctrl+Shift+G)"
        onClick={() => run('ungroup', () => ungroupSelection(doc, selection))}
      >
        Ungroup
      </button>
    </>
  );
}
