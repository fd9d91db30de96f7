/**
 * Full-size 3D samples in bands. A sphere-traced frame at full size can take seconds on a software
 * or weak GPU, and one draw call that long blocks the page (and risks the driver's watchdog), so
 * such a sample is drawn as horizontal bands from the top down, one at a time (frame-schedule.ts),
 * each shown as soon as it is finished. A band is sized to take about BAND_MS: the first from the
 * frame time predicted by render-scale.ts's model (t(1) = t_m / s_m² for a frame of scale s_m
 * that took t_m), every later one from the measured time of the band before less one frame
 * interval (a band is seen finished only when a frame polls its fence); one seen finished at its
 * first poll, or within a frame interval, grows by MAX_GROWTH (frame-schedule.ts).
 */

/** Bands are aimed at this many ms each. */
export const BAND_MS = 50;
/**
 * A band grows at most this much over the one before: a fast band's time is rounded up to a
 * display frame (it is seen by polling a fence), and the model behind the first band is rough.
 */
export const MAX_GROWTH = 2;

const isTime = (ms: number) => ms > 0 && Number.isFinite(ms);

/**
 * The rows of the first band of a full-size sample predicted to take `predictedMs` over `rows`
 * rows: all of them (one whole draw) when it takes at most `bandMs` or the prediction is not a
 * positive finite number; else those that take about `bandMs`, at least one.
 */
export function firstBandRows(predictedMs: number, rows: number, bandMs: number = BAND_MS): number {
  if (!isTime(predictedMs) || !(predictedMs > bandMs)) return rows;
  return Math.max(1, Math.floor((rows * Math.max(0, bandMs)) / predictedMs));
}

/**
 * The rows of the next band after one of `last` rows took `ms`: those that take about `bandMs` at
 * that pace, at most MAX_GROWTH × `last`, at least one, at most `rows`. A time that is not a
 * positive finite number keeps `last`.
 */
export function nextBandRows(last: number, ms: number, rows: number, bandMs: number = BAND_MS): number {
  if (!isTime(ms)) return last;
  const paced = Math.round((last * Math.max(0, bandMs)) / ms);
  return Math.max(1, Math.min(paced, last * MAX_GROWTH, rows));
}

/**
 * The rows of the next band after one of `last` rows whose fence was already signalled when it was
 * first polled: its GPU time is unknown, only below a display frame (on a loaded machine that can
 * be hundreds of ms, and pacing by it would keep one-row bands for ever), so it grows by MAX_GROWTH.
 */
export const grownBandRows = (last: number, rows: number): number =>
  Math.max(1, Math.min(last * MAX_GROWTH, rows));

/**
 * GL rows [y0, y1) (counted from the bottom, as gl.scissor counts them) of a band of `count` rows
 * that follows `done` rows drawn from the top of a `height`-row picture; clipped at the bottom.
 */
export function bandRows(done: number, count: number, height: number): readonly [number, number] {
  const y1 = height - done;
  return [Math.max(0, y1 - count), y1];
}
