/**
 * A progress line on stderr for long renders: redrawn in place on a terminal; in a log (not a
 * terminal) one line per quarter, so CI output stays short, and one at least every half minute
 * in between, so a render of hours is seen to move. Once a few percent are done (or some seconds
 * have passed) it adds the time left, extrapolated from the time so far: left = elapsed · (1 − f) / f.
 */
import type { CliOutput } from './command.ts';
import { formatDuration } from './render-estimate.ts';

export interface Progress {
  update(fraction: number): void;
  /** Ends the line (on a terminal) so later output starts on a fresh one. */
  finish(): void;
}

const LOG_STEP = 25;
/** A log gets a line at least this often (ms) between quarters. */
const LOG_EVERY_MS = 30_000;
/** A terminal is redrawn at most this often (ms) while the whole percent stays the same. */
const TTY_EVERY_MS = 1_000;

/** Below this fraction done, and before this much time (ms), the time left is not worth guessing. */
const LEFT_AFTER = 0.02;
const LEFT_AFTER_MS = 20_000;

/** Tenths of a percent, since 1 % of a render of hours is minutes. */
const tenths = (f: number) => `${(Math.floor(f * 1000) / 10).toFixed(1)}%`;

export function progressLine(
  out: CliOutput,
  label: string,
  now: () => number = () => performance.now(),
): Progress {
  let shown = -1;
  let drawn = '';
  const started = now();
  let last = started;
  const left = (fraction: number) => {
    const elapsed = now() - started;
    return fraction > 0 && fraction < 1 && (fraction >= LEFT_AFTER || elapsed >= LEFT_AFTER_MS)
      ? ` (about ${formatDuration((elapsed / 1000) * ((1 - fraction) / fraction))} left)`
      : '';
  };
  return {
    update(fraction) {
      const f = Math.min(1, Math.max(0, fraction));
      const percent = Math.floor(f * 100);
      const t = now();
      if (out.isTTY) {
        const text = `${label} ${tenths(f).padStart(6)}${left(f)}`;
        if (text === drawn || (percent === shown && t - last < TTY_EVERY_MS)) return;
        // Pad so a shorter line fully overwrites a longer one.
        out.write(`\r${text.padEnd(drawn.length)}`);
        drawn = text;
        shown = percent;
        last = t;
        return;
      }
      const step = Math.floor(percent / LOG_STEP) * LOG_STEP;
      if (step > shown && step > 0 && step < 100) {
        out.write(`${label} ${step}%${left(f)}\n`);
        shown = step;
        last = t;
      } else if (f < 1 && t - last >= LOG_EVERY_MS) {
        out.write(`${label} ${tenths(f)}${left(f)}\n`);
        last = t;
      }
    },
    finish() {
      if (out.isTTY && shown >= 0) out.write(`\r${`${label} 100%`.padEnd(drawn.length)}\n`);
    },
  };
}
