/** Long CPU renders say up front how long they will take, and how long is left as they go. */
import { describe, expect, it } from 'vitest';
import { progressLine } from '../../../src/cli/progress.ts';
import {
  ANNOUNCE_AFTER_S,
  announceEstimate,
  estimateRenderSeconds,
  formatDuration,
} from '../../../src/cli/render-estimate.ts';
import { loadExample } from '../../support/examples.ts';

const sink = (isTTY = false) => {
  const lines: string[] = [];
  return { out: { isTTY, write: (s: string) => void lines.push(s) }, lines };
};

describe('render estimate', () => {
  it('formats durations as a person reads them', () => {
    expect(formatDuration(0.25)).toBe('250 ms');
    expect(formatDuration(42.4)).toBe('42 s');
    expect(formatDuration(185)).toBe('3 min 5 s');
    expect(formatDuration(4320)).toBe('1 h 12 min');
    expect(formatDuration(Number.NaN)).toBe('an unknown time');
  });

  it('announces only renders that take a while', () => {
    const short = sink();
    expect(announceEstimate(short.out, 'rendering x.png', ANNOUNCE_AFTER_S / 2)).toBe(false);
    expect(short.lines).toEqual([]);
    const long = sink();
    expect(announceEstimate(long.out, 'rendering x.png', 125)).toBe(true);
    expect(long.lines.join('')).toMatch(/^rendering x\.png: about 2 min 5 s on the CPU/);
  });

  it('estimates from a probe of the real scene (finite, positive)', () => {
    const { scene } = loadExample('hyperbolic-237');
    const s = estimateRenderSeconds(scene, 16384, 16384, 4);
    expect(Number.isFinite(s)).toBe(true);
    expect(s).toBeGreaterThan(0);
  });

  it('adds the time left to the progress line, extrapolated from the time so far', () => {
    let t = 0;
    const log = sink(false);
    const p = progressLine(log.out, 'rendering big.png', () => t);
    t = 10_000; // 10 s for the first quarter
    p.update(0.25);
    t = 20_000;
    p.update(0.5);
    expect(log.lines).toEqual([
      'rendering big.png 25% (about 30 s left)\n',
      'rendering big.png 50% (about 20 s left)\n',
    ]);
  });

  it('in a log, writes a line at least every half minute between quarters, with the time left', () => {
    let t = 0;
    const log = sink(false);
    const p = progressLine(log.out, 'rendering huge.png', () => t);
    t = 10_000;
    p.update(0.001);
    t = 31_000;
    p.update(0.002);
    t = 40_000;
    p.update(0.003);
    expect(log.lines).toEqual(['rendering huge.png 0.2% (about 4 h 17 min left)\n']);
  });

  it('on a terminal, redraws each second, in tenths of a percent', () => {
    let t = 0;
    const tty = sink(true);
    const p = progressLine(tty.out, 'r', () => t);
    p.update(0.001);
    t = 500;
    p.update(0.002); // under a second, same whole percent: not redrawn
    t = 1_500;
    p.update(0.003);
    p.finish();
    expect(tty.lines).toEqual(['\rr   0.1%', '\rr   0.3%', '\rr 100%  \n']);
  });
});
