/**
 * Long CPU renders say up front how long they will take, and how long is left as they go. A volume
 * render is estimated from its own cost: the samples its rays take (the renderer's count, early
 * exits and rays past the mirrors included) × the time of one sample.
 */
import { describe, expect, it } from 'vitest';
import { probeVolume3d } from '../../../shader-gen/space/render-3d.ts';
import { progressLine } from '../../../src/cli/progress.ts';
import {
  ANNOUNCE_AFTER_S,
  announceEstimate,
  estimate3d,
  estimateRenderSeconds,
  estimateVolume3d,
  formatDuration,
} from '../../../src/cli/render-estimate.ts';
import { FIG11 } from '../../shader-gen/space/scenes-3d.ts';
import { NO_MIRRORS, ONE_MIRROR, VOLUME } from '../../shader-gen/space/volume-scenes.ts';
import { loadExample } from '../../support/examples.ts';

/** The mean samples a ray of a small W × H render takes (every pixel: the probe's grid covers them all). */
const meanSamples = (scene: typeof ONE_MIRROR, w: number, h: number) => {
  const p = probeVolume3d(scene, w, h);
  let sum = 0;
  for (let i = 2; i < p.length; i += 4) sum += p[i]!;
  return sum / (w * h);
};

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

  it('estimates a volume render from the samples its rays take, × the time of one sample', () => {
    const e = estimateVolume3d(ONE_MIRROR, 24, 18, 4);
    expect(e.samplesPerRay).toBeCloseTo(meanSamples(ONE_MIRROR, 24, 18), 9);
    expect(e.samplesPerRay).toBeGreaterThan(0);
    expect(e.samplesPerRay).toBeLessThan(VOLUME.steps); // the rays past the mirror take none
    expect(e.steps).toBe(VOLUME.steps);
    expect(e.secondsPerSample).toBeGreaterThan(0);
    expect(e.seconds).toBeCloseTo(24 * 18 * 4 * e.samplesPerRay * e.secondsPerSample, 12);
    // Twice the samples asked for, twice the samples taken (nothing here is dense enough to stop early).
    const twice = { ...ONE_MIRROR, volume: { ...VOLUME, steps: 2 * VOLUME.steps } };
    expect(estimateVolume3d(twice, 24, 18, 4).samplesPerRay).toBeCloseTo(2 * e.samplesPerRay, 9);
    // A dense cloud stops its rays early: fewer samples taken than asked for by the rays that meet it.
    const dense = { ...ONE_MIRROR, volume: { ...VOLUME, density: 40 } };
    expect(estimateVolume3d(dense, 24, 18, 4).samplesPerRay).toBeLessThan(e.samplesPerRay / 2);
    // No mirrors: no ray takes a sample, the render costs nothing worth announcing.
    expect(estimateVolume3d(NO_MIRRORS, 24, 18, 4)).toMatchObject({ samplesPerRay: 0, seconds: 0 });
  });

  it('says how a 3D render is drawn: sphere traced, or volume rendered with its samples per ray', () => {
    expect(estimate3d(ONE_MIRROR, 24, 18, 1).how).toMatch(
      /^volume rendered, about \d+ of 64 samples per ray$/,
    );
    const surface = { ...FIG11, marchSteps: 16 };
    const s = estimate3d(surface, 8, 6, 1);
    expect(s.how).toBe('sphere traced');
    expect(s.seconds).toBeGreaterThan(0);
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
