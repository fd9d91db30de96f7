/**
 * Dynamic resolution for the 3D pane, as pure policy (the GL side is dynamic-resolution.ts).
 * A sphere-traced frame costs seconds on SwiftShader and weak GPUs, so while the user interacts
 * (orbit, zoom, a handle drag, a value edit) the picture is drawn at a reduced scale s (each side
 * × s) chosen from the last measured frame time; once still it is drawn again at full size and
 * accumulates its samples as before. The 2D pane never uses this (its frames are cheap).
 *
 * The model: a frame's time is proportional to its pixel count, t(s) = t_m · (s / s_m)² for a
 * frame measured at scale s_m taking t_m, so a time T needs s = s_m · √(T / t_m).
 */

export interface ScalePolicy {
  /** The band of frame times (ms) a reduced frame aims at; inside it the scale is kept (hysteresis). */
  readonly lowMs: number;
  readonly highMs: number;
  /** The smallest scale (each side); the largest is 1. */
  readonly minScale: number;
  /** A step up multiplies the scale by at most this (the model is rough for small frames). */
  readonly maxStepUp: number;
  /** Scales are multiples of this, so near-equal measurements give the same target size. */
  readonly quantum: number;
  /** Stillness (ms since the last change) after which the picture is drawn at full size. */
  readonly settleMs: number;
}

export const DEFAULT_SCALE_POLICY: ScalePolicy = {
  lowMs: 30,
  highMs: 60,
  minScale: 1 / 8,
  maxStepUp: 1.5,
  quantum: 1 / 32,
  settleMs: 250,
};

export interface FrameMeasurement {
  /** GPU time of one frame, ms (submit to fence signalled). */
  readonly ms: number;
  /** The scale that frame was drawn at. */
  readonly scale: number;
}

const clamp = (x: number, lo: number, hi: number) => Math.min(hi, Math.max(lo, x));

/**
 * The scale of the next interactive frame: `current` while the time it predicts for `current`
 * lies in [lowMs, highMs]; otherwise the scale predicting the band's geometric middle √(low·high),
 * at most `maxStepUp` × `current` when going up, rounded down to a multiple of `quantum` and
 * bounded by [minScale, 1]. A measurement that is not finite or not positive changes nothing.
 */
export function nextRenderScale(
  current: number,
  m: FrameMeasurement,
  p: ScalePolicy = DEFAULT_SCALE_POLICY,
): number {
  if (!(m.ms > 0 && Number.isFinite(m.ms) && m.scale > 0)) return current;
  const predicted = m.ms * (current / m.scale) ** 2;
  if (predicted >= p.lowMs && predicted <= p.highMs) return current;
  const ideal = m.scale * Math.sqrt(Math.sqrt(p.lowMs * p.highMs) / m.ms);
  const capped = ideal > current ? Math.min(ideal, current * p.maxStepUp) : ideal;
  const quantised = Math.floor(capped / p.quantum + 1e-9) * p.quantum;
  return clamp(quantised, p.minScale, 1);
}

/** Whether a change `sinceChangeMs` ago still counts as interaction (reduced frames). */
export const interacting = (sinceChangeMs: number, p: ScalePolicy = DEFAULT_SCALE_POLICY): boolean =>
  sinceChangeMs < p.settleMs;

/** The pixel size of a frame drawn at `scale` of a width×height buffer (at least 1×1). */
export function scaledSize(
  width: number,
  height: number,
  scale: number,
): { readonly width: number; readonly height: number } {
  if (scale >= 1) return { width, height };
  return { width: Math.max(1, Math.round(width * scale)), height: Math.max(1, Math.round(height * scale)) };
}
