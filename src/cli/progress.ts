/**
 * A progress line on stderr for long renders: redrawn in place on a terminal; in a log (not a
 * terminal) one line per quarter, so CI output stays short.
 */
import type { CliOutput } from './command.ts';

export interface Progress {
  update(fraction: number): void;
  /** Ends the line (on a terminal) so later output starts on a fresh one. */
  finish(): void;
}

const LOG_STEP = 25;

export function progressLine(out: CliOutput, label: string): Progress {
  let shown = -1;
  return {
    update(fraction) {
      const percent = Math.floor(Math.min(1, Math.max(0, fraction)) * 100);
      if (out.isTTY) {
        if (percent !== shown) out.write(`\r${label} ${String(percent).padStart(3)}%`);
        shown = percent;
        return;
      }
      const step = Math.floor(percent / LOG_STEP) * LOG_STEP;
      if (step > shown && step > 0 && step < 100) {
        out.write(`${label} ${step}%\n`);
        shown = step;
      }
    },
    finish() {
      if (out.isTTY && shown >= 0) out.write(`\r${label} 100%\n`);
    },
  };
}
