/**
 * The run of an export dialog (PNG, animation): progress while it renders, Cancel, the error if it
 * fails, and closing the dialog once the file is out. One place for the state both dialogs share.
 */
import { useRef, useState } from 'react';

/** Renders and downloads; resolves false when cancelled. `onProgress` returning false cancels. */
export type ExportRun = (onProgress: (fraction: number) => boolean) => Promise<boolean>;

export interface ExportRunState {
  /** Fraction done while running (0..1), null when idle. */
  readonly progress: number | null;
  readonly error: string | null;
  start(run: ExportRun): Promise<void>;
  /** Asks the running export to stop at its next progress report. */
  cancel(): void;
  /** Cancels whatever runs and closes the dialog. */
  close(): void;
}

export function useExportRun(onClose: () => void): ExportRunState {
  const [progress, setProgress] = useState<number | null>(null);
  const [error, setError] = useState<string | null>(null);
  const cancelled = useRef(false);
  return {
    progress,
    error,
    async start(run) {
      cancelled.current = false;
      setError(null);
      setProgress(0);
      try {
        const done = await run((f) => {
          setProgress(f);
          return !cancelled.current;
        });
        setProgress(null);
        if (done) onClose();
      } catch (e) {
        setProgress(null);
        setError(`The export failed: ${(e as Error).message}`);
      }
    },
    cancel() {
      cancelled.current = true;
    },
    close() {
      cancelled.current = true;
      onClose();
    },
  };
}
