/** A short confirmation ("Link copied") that fades by itself; errors stay until dismissed. */
import { useEffect } from 'react';

export interface ToastMessage {
  readonly id: number;
  readonly kind: 'ok' | 'error';
  readonly text: string;
}

/** How long a confirmation stays on screen once it has been painted. */
const TOAST_MS = 5000;

export function Toast({ toast, onDone }: { toast: ToastMessage; onDone(): void }) {
  useEffect(() => {
    if (toast.kind === 'error') return undefined;
    // The countdown starts at the first frame that shows it: loading an example compiles a shader,
    // which can hold the page for seconds, and the toast must not fade unseen meanwhile.
    let t: ReturnType<typeof setTimeout> | undefined;
    const frame = requestAnimationFrame(() => {
      t = setTimeout(onDone, TOAST_MS);
    });
    return () => {
      cancelAnimationFrame(frame);
      clearTimeout(t);
    };
  }, [toast, onDone]);
  return (
    <div
      className={`kf-toast kf-toast--${toast.kind}`}
      role={toast.kind === 'error' ? 'alert' : 'status'}
      data-testid="toast"
    >
      <span>{toast.text}</span>
      <button type="button" className="kf-icon-button" aria-label="Dismiss" onClick={onDone}>
        ×
      </button>
    </div>
  );
}
