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
