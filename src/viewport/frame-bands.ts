/**
 * Full-size 3D samples in bands. A sphere-traced frame at full size can take seconds on a software
 * or weak GPU, and one draw call that long blocks the page (and risks the driver's watchdog), so
 * the viewport draws such a sample as horizontal bands, one per animation frame, and shows it once
 * every band is drawn. The frame time is predicted from the last timed frame with the model of
 * render-scale.ts: t(1) = t_m / s_m² for a frame of scale s_m that took t_m.
 */

/** Bands are aimed at this many ms each. */
export const BAND_MS = 50;
/** At most this many bands (each at least one row). */
export const MAX_BANDS = 64;

/**
 * How many bands a full-size sample predicted to take `predictedMs` is drawn in: 1 (a whole
 * frame) when it takes at most `bandMs`, else ⌈predicted / bandMs⌉, at most MAX_BANDS and at most
 * one per row. A prediction that is not a positive finite number gives 1.
 */
export function bandCount(predictedMs: number, rows: number, bandMs: number = BAND_MS): number {
  if (!(predictedMs > 0 && Number.isFinite(predictedMs)) || predictedMs <= bandMs) return 1;
  const wanted = bandMs > 0 ? Math.ceil(predictedMs / bandMs) : MAX_BANDS;
  return Math.max(1, Math.min(wanted, MAX_BANDS, Math.floor(rows)));
}

/** Rows [y0, y1) of band i of n over `rows` rows: consecutive, covering every row once, sizes differing by at most 1. */
export function bandRows(i: number, n: number, rows: number): readonly [number, number] {
  return [Math.floor((i * rows) / n), Math.floor(((i + 1) * rows) / n)];
}
