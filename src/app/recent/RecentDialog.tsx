/**
 * Recent documents: what this browser autosaved (any tab, any session), newest first, each a button
 * with its picture, title and when it was saved. A list of buttons, so Tab and Enter reach every
 * one; Escape closes. Styled like the Examples gallery, which it resembles. Each entry but the one this
 * tab is editing (it would be saved again at the next change) has a Remove button; the last removal
 * can be undone from the dialog, so a slip of the finger costs nobody their work.
 */
import { useEffect, useRef, useState } from 'react';
import type { GraphDoc } from '../../../nodes/graph/document.ts';
import { parseDocumentText } from '../../../nodes/graph/load.ts';
import { registry } from '../../../nodes/types/index.ts';
import type { RecentEntry } from '../../state/recent-docs.ts';
import { loadedMessage } from '../io/use-document-io.tsx';
import { useModalDialog } from '../use-modal-dialog.ts';
import { RECENT_UNAVAILABLE, type Recent } from './use-recent.ts';

interface Props {
  /** null while the list is read; a message when it cannot be. */
  readonly entries: readonly RecentEntry[] | null | string;
  /** The entry this tab is editing (marked, so nobody wonders where the current work went). */
  readonly currentId: string;
  onOpen(entry: RecentEntry): void;
  onRemove(entry: RecentEntry): void;
  /** The entry removed last, while it can still be put back. */
  readonly removed: RecentEntry | null;
  onUndoRemove(): void;
  onClose(): void;
}

const when = (ms: number) =>
  new Date(ms).toLocaleString(undefined, { dateStyle: 'medium', timeStyle: 'short' });

export function RecentDialog({
  entries,
  currentId,
  onOpen,
  onRemove,
  removed,
  onUndoRemove,
  onClose,
}: Props) {
  const dialog = useModalDialog(onClose);
  const heading = useRef<HTMLHeadingElement>(null);
  // Opened with Enter, the key's keypress comes after showModal focused the first button (close):
  // that would close the dialog at once. The heading takes focus instead; Tab goes on to the list.
  useEffect(() => heading.current?.focus(), []);
  return (
    <dialog
      ref={dialog.ref}
      className="kf-dialog kf-gallery"
      aria-labelledby="kf-recent-title"
      onClose={dialog.onClose}
    >
      <header className="kf-dialog__header">
        <h2 id="kf-recent-title" ref={heading} tabIndex={-1}>
          Recent
        </h2>
        <button type="button" className="kf-icon-button" aria-label="Close recent" onClick={onClose}>
          ×
        </button>
      </header>
      <p className="kf-dialog__lead">Documents this browser saved as you worked, in any tab.</p>
      {removed && (
        <p role="status" className="kf-recent__removed">
          Removed “{removed.title}”.{' '}
          <button
            type="button"
            className="kf-link"
            aria-label={`Undo removing “${removed.title}”`}
            onClick={onUndoRemove}
          >
            Undo
          </button>
        </p>
      )}
      {entries === null && <p role="status">Reading…</p>}
      {typeof entries === 'string' && <p role="status">{entries}</p>}
      {Array.isArray(entries) && entries.length === 0 && <p role="status">Nothing saved yet.</p>}
      {Array.isArray(entries) && entries.length > 0 && (
        <ul className="kf-gallery__cards" aria-label="Recent documents">
          {entries.map((e) => (
            <li key={e.id} className="kf-recent__entry">
              <button type="button" className="kf-gallery__card" onClick={() => onOpen(e)}>
                {e.thumbnail ? (
                  <img src={e.thumbnail} alt="" width={96} height={96} />
                ) : (
                  <span className="kf-gallery__nothumb" aria-hidden />
                )}
                <span className="kf-gallery__text">
                  <strong>{e.title}</strong>
                  <span>
                    <time dateTime={new Date(e.savedAt).toISOString()}>{when(e.savedAt)}</time>
                    {e.id === currentId ? ' · open in this tab' : ''}
                  </span>
                </span>
              </button>
              {e.id !== currentId && (
                <button
                  type="button"
                  className="kf-icon-button kf-recent__remove"
                  aria-label={`Remove “${e.title}” from Recent`}
                  title="Remove from Recent"
                  onClick={() => onRemove(e)}
                >
                  ×
                </button>
              )}
            </li>
          ))}
        </ul>
      )}
    </dialog>
  );
}

/**
 * The dialog with the browser's list; a pick is parsed (and migrated) like any opened file and
 * replaces the graph as one undo step, like an example.
 */
export function RecentPanel({
  recent,
  load,
  notify,
}: {
  readonly recent: Recent;
  load(doc: GraphDoc, label: string, recentId: string): void;
  notify(text: string): void;
}) {
  const [entries, setEntries] = useState<readonly RecentEntry[] | null | string>(null);
  const [removed, setRemoved] = useState<RecentEntry | null>(null);
  /** Bumped to read the list again after a removal or its undo. */
  const [version, setVersion] = useState(0);
  // biome-ignore lint/correctness/useExhaustiveDependencies: `version` is the re-read trigger.
  useEffect(() => {
    let live = true;
    recent.store.list().then(
      (list) => live && setEntries(list),
      () => live && setEntries(RECENT_UNAVAILABLE),
    );
    return () => {
      live = false;
    };
  }, [recent.store, version]);
  const failed = () => setEntries(RECENT_UNAVAILABLE);
  const remove = (entry: RecentEntry) =>
    recent.store.remove(entry.id).then(() => {
      setRemoved(entry);
      setVersion((v) => v + 1);
    }, failed);
  const undoRemove = () => {
    if (!removed) return;
    recent.store.put(removed).then(() => {
      setRemoved(null);
      setVersion((v) => v + 1);
    }, failed);
  };
  const open = (entry: RecentEntry) => {
    const loaded = parseDocumentText(entry.text, registry);
    if (!loaded.ok) {
      setEntries(`“${entry.title}” could not be read: ${loaded.diagnostics[0]?.message ?? 'unknown'}`);
      return;
    }
    load(loaded.doc, `open ${entry.title}`, entry.id);
    recent.setOpen(false);
    notify(loadedMessage(`“${entry.title}”`));
  };
  return (
    <RecentDialog
      entries={entries}
      currentId={recent.currentId()}
      onOpen={open}
      onRemove={remove}
      removed={removed}
      onUndoRemove={undoRemove}
      onClose={() => recent.setOpen(false)}
    />
  );
}
