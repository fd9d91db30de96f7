/** A short confirmation ("Link copied") that fades by itself; errors stay until dismissed. */
import { useEffect } from 'react';

export interface ToastMessage {
  readonly id: number;
  readonly kind: 'ok' | 'error';
  readonly text: string;
}

/** How long a confirmation stays on screen. */
const TOAST_MS = 3500;

export function Toast({ toast, onDone }: { toast: ToastMessage; onDone(): void }) {
  useEffect(() => {
    if (toast.kind === 'error') return undefined;
    const t = setTimeout(onDone, TOAST_MS);
    return () => clearTimeout(t);
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
