/**
 * How long a CPU render will take, said before it starts: a small probe of the same picture at
 * the same sample count is rendered and timed, and the time per pixel is scaled to the full size.
 * The plane's probe is the whole view at coarser pixels (its cost per pixel does not depend on
 * the pixel size); space's probe is a spread of the render's own pixels, since the sphere tracer
 * marches closer to the surface, so longer, the smaller a pixel is.
 */
import type { Scene } from '../../nodes/core/scene.ts';
import type { Scene3d } from '../../nodes/core/scene-3d.ts';
import { rasterize } from '../../shader-gen/raster.ts';
import { render3dFrame, renderPixel3d } from '../../shader-gen/space/render-3d.ts';
import type { CliOutput } from './command.ts';
import { scenePictures } from './scene-pictures.ts';

/** The probe: PROBE_SIDE² pixels at the render's aspect ratio. */
const PROBE_SIDE = 48;
/** Renders expected to take at least this long are announced. */
export const ANNOUNCE_AFTER_S = 5;

/** The 3D probe stops after this many seconds (a few hundred pixels of a costly scene are enough). */
const PROBE_3D_S = 0.5;
/** …but traces at least this many pixels, so one odd pixel does not make the estimate. */
const PROBE_3D_MIN = 16;

/** Seconds of the whole render: `probe` (which returns how many pixels it did) timed, scaled to `pixels`. */
function scaledProbe(pixels: number, probe: () => number): number {
  const started = performance.now();
  const done = probe();
  return (((performance.now() - started) / 1000) * pixels) / Math.max(1, done);
}

/** Seconds the full render should take: probe time × (W·H) / (probe pixels). */
export function estimateRenderSeconds(scene: Scene, width: number, height: number, samples: number): number {
  const scale = Math.sqrt((PROBE_SIDE * PROBE_SIDE) / (width * height));
  const pw = Math.max(1, Math.min(width, Math.round(width * scale)));
  const ph = Math.max(1, Math.min(height, Math.round(height * scale)));
  const pictures = scenePictures(scene);
  return scaledProbe(width * height, () => {
    rasterize(scene, { width: pw, height: ph, samples, pictures });
    return pw * ph;
  });
}

/**
 * Seconds a 3D render takes on one thread: the render's own pixels at the centres of a grid of
 * cells, visited in a scattered order (a stride coprime to the cell count reaches every cell once),
 * so wherever the time box stops them they cover the picture, sky and surface alike.
 */
export function estimateRender3dSeconds(
  scene: Scene3d,
  width: number,
  height: number,
  samples: number,
): number {
  const frame = render3dFrame(scene, width, height, { samples });
  const gx = Math.min(PROBE_SIDE, width);
  const gy = Math.min(PROBE_SIDE, height);
  const cells = gx * gy;
  let stride = Math.max(1, Math.round(cells * 0.618));
  while (gcd(stride, cells) !== 1) stride++;
  const pixel = new Uint8ClampedArray(4);
  return scaledProbe(width * height, () => {
    const until = performance.now() + PROBE_3D_S * 1000;
    let n = 0;
    for (; n < cells && (n < PROBE_3D_MIN || performance.now() < until); n++) {
      const c = (n * stride) % cells;
      const px = Math.floor((((c % gx) + 0.5) * width) / gx);
      const row = Math.floor(((Math.floor(c / gx) + 0.5) * height) / gy);
      renderPixel3d(frame, px, row, pixel, 0);
    }
    return n;
  });
}

const gcd = (a: number, b: number): number => (b === 0 ? a : gcd(b, a % b));

/** "850 ms", "42 s", "3 min 5 s", "1 h 12 min". */
export function formatDuration(seconds: number): string {
  if (!Number.isFinite(seconds) || seconds < 0) return 'an unknown time';
  if (seconds < 1) return `${Math.max(1, Math.round(seconds * 1000))} ms`;
  const s = Math.round(seconds);
  if (s < 60) return `${s} s`;
  if (s < 3600) return `${Math.floor(s / 60)} min ${s % 60} s`;
  return `${Math.floor(s / 3600)} h ${Math.floor((s % 3600) / 60)} min`;
}

export interface AnnounceOptions {
  /** Say it however short the render (`kleinflow render --progress`). */
  readonly always?: boolean;
  /** What it runs on ("the CPU"; "2 CPU threads" for a render split over workers). */
  readonly on?: string;
}

/** Says the estimate on stderr when the render will take a while; returns whether it did. */
export function announceEstimate(
  out: CliOutput,
  what: string,
  seconds: number,
  options: AnnounceOptions = {},
): boolean {
  if (!(options.always || seconds >= ANNOUNCE_AFTER_S)) return false;
  const on = options.on ?? 'the CPU';
  out.write(`${what}: about ${formatDuration(seconds)} on ${on} (estimated from a small probe render)\n`);
  return true;
}
