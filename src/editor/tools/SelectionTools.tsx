/**
 * Toolbar buttons that act on the selected nodes: Mute (M), Frame. Each is one undo step.
 */
import { useEditorState, useStore } from '../../state/use-store.ts';
import { frameAround } from './frames.ts';
import { allMuted, muteToggle } from './mute.ts';

export function SelectionTools() {
  const store = useStore();
  const doc = useEditorState((s) => s.doc);
  const selection = useEditorState((s) => s.selection);
  const some = doc.nodes.some((n) => selection.has(n.id));
  const muted = allMuted(doc, selection);
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
    </>
  );
}
