/**
 * The frame every export dialog shares (PNG, animation, STL): a modal <dialog> whose Escape goes
 * through `onClose` (so a running export is cancelled, not abandoned), a header with the title and
 * a close button, and one lead paragraph saying how the file is made.
 */
import type { ReactNode, RefObject } from 'react';

interface Props {
  readonly dialogRef: RefObject<HTMLDialogElement | null>;
  /** The heading, also the dialog's accessible name. */
  readonly title: string;
  readonly lead: ReactNode;
  onClose(): void;
  readonly children: ReactNode;
}

export function ExportDialogShell({ dialogRef, title, lead, onClose, children }: Props) {
  return (
    <dialog
      ref={dialogRef}
      className="kf-dialog kf-export"
      aria-label={title}
      onCancel={(e) => {
        e.preventDefault();
        onClose();
      }}
    >
      <header className="kf-dialog__header">
        <h2>{title}</h2>
        <button type="button" className="kf-icon-button" aria-label="Close export" onClick={onClose}>
          ×
        </button>
      </header>
      <p className="kf-dialog__lead">{lead}</p>
      {children}
    </dialog>
  );
}

interface RunProps {
  /** 0…1 while the export runs, null when it does not. */
  readonly progress: number | null;
  /** What is happening at `progress`, shown beside the bar. */
  progressText(progress: number): string;
  readonly error: string | null;
  /** The primary button's text, e.g. "Export 800 × 600". */
  readonly startLabel: ReactNode;
  readonly startDisabled?: boolean;
  onStart(): void;
  onCancel(): void;
  onClose(): void;
}

/**
 * The end of every export dialog: the progress bar while the export runs, its error if it failed,
 * and the actions — Cancel while running, else Close and the export button.
 */
export function ExportRunFooter(p: RunProps) {
  return (
    <>
      {p.progress !== null && (
        <div className="kf-export__progress">
          <progress max={1} value={p.progress} aria-label="Export progress" />
          <span>{p.progressText(p.progress)}</span>
        </div>
      )}
      {p.error && (
        <p className="kf-export__error" role="alert">
          {p.error}
        </p>
      )}
      <footer className="kf-export__actions">
        {p.progress !== null ? (
          <button type="button" className="kf-button" onClick={p.onCancel}>
            Cancel
          </button>
        ) : (
          <>
            <button type="button" className="kf-button" onClick={p.onClose}>
              Close
            </button>
            <button
              type="button"
              className="kf-button kf-button--primary"
              disabled={p.startDisabled}
              onClick={p.onStart}
            >
              {p.startLabel}
            </button>
          </>
        )}
      </footer>
    </>
  );
}
