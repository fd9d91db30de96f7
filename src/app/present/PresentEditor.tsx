/**
 * The author's side of the presentation: title, description and the note of the current step
 * (plain text or the small Markdown subset of markdown.tsx), each one undo step, stored in the
 * document's `meta` so they travel with files, PNGs and links. Plus the class-page links.
 */
import { NOTE_MAX_CHARS } from '../../../nodes/graph/document.ts';
import { useEditorState, useStore } from '../../state/use-store.ts';
import type { ConstructionStep } from './construction-steps.ts';
import { DraftText } from './DraftText.tsx';
import { ShareBox } from './ShareBox.tsx';

const TITLE_MAX = 500;
const DESCRIPTION_MAX = 20_000;

export function PresentEditor({ step, number }: { step: ConstructionStep | undefined; number: number }) {
  const store = useStore();
  const meta = useEditorState((s) => s.doc.meta);
  const setMeta = (patch: Partial<typeof meta>, label: string) =>
    store.dispatch({ type: 'set-meta', meta: { ...store.getState().doc.meta, ...patch } }, label);
  const setNote = (nodeId: string, text: string) => {
    const { meta: now, nodes } = store.getState().doc;
    // Notes of nodes deleted since are dropped here, so they never count against NOTES_MAX.
    const ids = new Set(nodes.map((n) => n.id));
    const rest = Object.entries(now.stepNotes ?? {}).filter(([id]) => id !== nodeId && ids.has(id));
    const stepNotes = Object.fromEntries(text.trim() ? [...rest, [nodeId, text]] : rest);
    setMeta({ stepNotes }, `edit the note of step ${number}`);
  };
  return (
    <aside className="kf-present-edit" aria-label="Presentation text">
      <h2 className="kf-present-edit__heading">Presentation text</h2>
      <DraftText
        label="Title"
        value={meta.title ?? ''}
        maxLength={TITLE_MAX}
        onCommit={(title) => setMeta({ title }, 'rename document')}
      />
      <DraftText
        label="Description"
        value={meta.description ?? ''}
        maxLength={DESCRIPTION_MAX}
        multiline
        placeholder="What the class will see, and why it matters"
        onCommit={(description) => setMeta({ description }, 'edit the description')}
      />
      {step ? (
        <DraftText
          key={step.nodeId}
          label={`Note for step ${number}: ${step.label}`}
          value={meta.stepNotes?.[step.nodeId] ?? ''}
          maxLength={NOTE_MAX_CHARS}
          multiline
          placeholder="What to say at this step"
          onCommit={(text) => setNote(step.nodeId, text)}
        />
      ) : (
        <p className="kf-present-edit__hint">Go to a step (▶ or the step list) to write its note.</p>
      )}
      <p className="kf-present-edit__hint">
        Text or Markdown: **bold**, *italic*, `code`, [link](https://…), lines starting “- ”. HTML is shown as
        text.
      </p>
      <ShareBox />
    </aside>
  );
}
