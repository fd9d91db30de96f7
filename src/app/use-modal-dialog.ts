/**
 * useModalDialog: a <dialog> shown modally while the component is mounted.
 *
 * Why not just `showModal()` in an effect and `close()` in its cleanup: React's StrictMode (what
 * `npm start` runs) mounts, cleans up and mounts again. The cleanup's `close()` queues a `close`
 * event that arrives after the second mount has reopened the dialog, and an `onClose` that trusts
 * it unmounts the dialog the moment it opened (Help "did nothing" under the dev server). So a
 * `close` event only counts while the dialog is really closed.
 */
import { type RefObject, useCallback, useEffect, useRef } from 'react';

const FOCUSABLE =
  'button:not([disabled]), [href], input:not([disabled]), select:not([disabled]), textarea:not([disabled]), [tabindex]:not([tabindex="-1"])';

export interface ModalDialog {
  readonly ref: RefObject<HTMLDialogElement | null>;
  /** Pass to the dialog's onClose (Escape, form method=dialog, close()). */
  readonly onClose: () => void;
}

export function useModalDialog(onClose: () => void): ModalDialog {
  const ref = useRef<HTMLDialogElement>(null);
  const latest = useRef(onClose);
  latest.current = onClose;
  useEffect(() => {
    const d = ref.current!;
    // What had the focus before: it gets it back when the dialog goes (see the cleanup).
    const opener = document.activeElement instanceof HTMLElement ? document.activeElement : null;
    if (!d.open) d.showModal();
    // showModal makes the page behind inert, but Tab can still leave the dialog for the browser's
    // own UI and come back to <body>: keep the keyboard cycling through the dialog's controls.
    const trap = (e: KeyboardEvent) => {
      if (e.key !== 'Tab') return;
      const focusable = [...d.querySelectorAll<HTMLElement>(FOCUSABLE)].filter(
        (el) => el.offsetParent !== null,
      );
      if (focusable.length === 0) return;
      const first = focusable[0];
      const last = focusable[focusable.length - 1];
      const inside = d.contains(document.activeElement);
      if (e.shiftKey && (!inside || document.activeElement === first)) {
        e.preventDefault();
        last.focus();
      } else if (!e.shiftKey && (!inside || document.activeElement === last)) {
        e.preventDefault();
        first.focus();
      }
    };
    d.addEventListener('keydown', trap);
    document.addEventListener('keydown', trap);
    return () => {
      d.removeEventListener('keydown', trap);
      document.removeEventListener('keydown', trap);
      if (d.open) d.close();
      // A dialog unmounted by its own choice (an example picked in the gallery) is already out of
      // the page, so the browser's close gives no focus back: the keyboard would start again at
      // the top of the page. Back to the control that opened it, unless something took the focus —
      // after the key event that closed it (Enter in the search box): given during its keydown, the
      // focus would take that key's click and open the dialog again.
      setTimeout(() => {
        const lost = document.activeElement === null || document.activeElement === document.body;
        if (lost && opener?.isConnected) opener.focus();
      }, 0);
    };
  }, []);
  const handleClose = useCallback(() => {
    if (ref.current?.open) return; // a stale close from a StrictMode remount: the dialog is open
    latest.current();
  }, []);
  return { ref, onClose: handleClose };
}
