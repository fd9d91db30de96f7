/**
 * How long a CPU render will take, said before it starts: a small probe of the same view at the
 * same sample count is rendered and timed, and the time per pixel is scaled to the full size. The
 * probe sees the same picture (same view, coarser pixels), so its cost per pixel is representative.
 */
import type { Scene } from '../../nodes/core/scene.ts';
import { rasterize } from '../../shader-gen/raster.ts';
import type { CliOutput } from './command.ts';
import { scenePictures } from './scene-pictures.ts';

/** The probe: PROBE_SIDE² pixels at the render's aspect ratio. */
const PROBE_SIDE = 48;
/** Renders expected to take at least this long are announced. */
export const ANNOUNCE_AFTER_S = 5;

/** Seconds the full render should take: probe time × (W·H) / (probe pixels). */
export function estimateRenderSeconds(scene: Scene, width: number, height: number, samples: number): number {
  const scale = Math.sqrt((PROBE_SIDE * PROBE_SIDE) / (width * height));
  const pw = Math.max(1, Math.min(width, Math.round(width * scale)));
  const ph = Math.max(1, Math.min(height, Math.round(height * scale)));
  const pictures = scenePictures(scene);
  const started = performance.now();
  rasterize(scene, { width: pw, height: ph, samples, pictures });
  const seconds = (performance.now() - started) / 1000;
  return (seconds * (width * height)) / (pw * ph);
}

/** "850 ms", "42 s", "3 min 5 s", "1 h 12 min". */
export function formatDuration(seconds: number): string {
  if (!Number.isFinite(seconds) || seconds < 0) return 'an unknown time';
  if (seconds < 1) return `${Math.max(1, Math.round(seconds * 1000))} ms`;
  const s = Math.round(seconds);
  if (s < 60) return `${s} s`;
  if (s < 3600) return `${Math.floor(s / 60)} min ${s % 60} s`;
  return `${Math.floor(s / 3600)} h ${Math.floor((s % 3600) / 60)} min`;
}

/** Says the estimate on stderr when the render will take a while; returns whether it did. */
export function announceEstimate(out: CliOutput, what: string, seconds: number): boolean {
  if (!(seconds >= ANNOUNCE_AFTER_S)) return false;
  out.write(`${what}: about ${formatDuration(seconds)} on the CPU (estimated from a small probe render)\n`);
  return true;
}
