/**
 * A progress line on stderr for long renders: redrawn in place on a terminal; in a log (not a
 * terminal) one line per quarter, so CI output stays short. Once a few percent are done it adds
 * the time left, extrapolated from the time so far: left = elapsed · (1 − f) / f.
 */
import type { CliOutput } from './command.ts';
import { formatDuration } from './render-estimate.ts';

export interface Progress {
  update(fraction: number): void;
  /** Ends the line (on a terminal) so later output starts on a fresh one. */
  finish(): void;
}

const LOG_STEP = 25;

/** Below this fraction done, the time left is not yet worth guessing. */
const LEFT_AFTER = 0.02;

export function progressLine(
  out: CliOutput,
  label: string,
  now: () => number = () => performance.now(),
): Progress {
  let shown = -1;
  const started = now();
  const left = (fraction: number) =>
    fraction >= LEFT_AFTER && fraction < 1
      ? ` (about ${formatDuration(((now() - started) / 1000) * ((1 - fraction) / fraction))} left)`
      : '';
  return {
    update(fraction) {
      const f = Math.min(1, Math.max(0, fraction));
      const percent = Math.floor(f * 100);
      if (out.isTTY) {
        // Pad so a shorter line fully overwrites a longer one.
        if (percent !== shown)
          out.write(`\r${label} ${String(percent).padStart(3)}%${left(f)}`.padEnd(label.length + 36));
        shown = percent;
        return;
      }
      const step = Math.floor(percent / LOG_STEP) * LOG_STEP;
      if (step > shown && step > 0 && step < 100) {
        out.write(`${label} ${step}%${left(f)}\n`);
        shown = step;
      }
    },
    finish() {
      if (out.isTTY && shown >= 0) out.write(`\r${label} 100%\n`);
    },
  };
}
