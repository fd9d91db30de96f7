/**
 * How long a CPU render will take, said before it starts: a small probe of the same picture at
 * the same sample count is rendered and timed, and the time per pixel is scaled to the full size.
 * The plane's probe is the whole view at coarser pixels (its cost per pixel does not depend on
 * the pixel size); space's probe is a spread of the render's own pixels, since the sphere tracer
 * marches closer to the surface, so longer, the smaller a pixel is. A volume render (docs/math-3d.md
 * "§11 Volume rendering of the nesting depth") marches nothing: its cost is its own, samples per
 * ray × the cost of one sample (a walk of the point), both measured on the same spread of rays.
 */
import type { Scene } from '../../nodes/core/scene.ts';
import type { Scene3d } from '../../nodes/core/scene-3d.ts';
import { rasterize } from '../../shader-gen/raster.ts';
import { rayDirection } from '../../shader-gen/space/camera-3d.ts';
import { render3dFrame, renderPixel3d } from '../../shader-gen/space/render-3d.ts';
import { volumeJitter, volumeRay } from '../../shader-gen/space/volume-3d.ts';
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
 * Visits the render's own pixels (px, row from the top) at the centres of a grid of cells, in a
 * scattered order (a stride coprime to the cell count reaches every cell once), so wherever the
 * time box stops them they cover the picture, sky and surface alike; returns how many it visited.
 */
function probePixels3d(width: number, height: number, visit: (px: number, row: number) => void): number {
  const gx = Math.min(PROBE_SIDE, width);
  const gy = Math.min(PROBE_SIDE, height);
  const cells = gx * gy;
  let stride = Math.max(1, Math.round(cells * 0.618));
  while (gcd(stride, cells) !== 1) stride++;
  const until = performance.now() + PROBE_3D_S * 1000;
  let n = 0;
  for (; n < cells && (n < PROBE_3D_MIN || performance.now() < until); n++) {
    const c = (n * stride) % cells;
    visit(
      Math.floor((((c % gx) + 0.5) * width) / gx),
      Math.floor(((Math.floor(c / gx) + 0.5) * height) / gy),
    );
  }
  return n;
}

/** Seconds a sphere-traced 3D render takes on one thread: the probe pixels rendered and timed. */
export function estimateRender3dSeconds(
  scene: Scene3d,
  width: number,
  height: number,
  samples: number,
): number {
  const frame = render3dFrame(scene, width, height, { samples });
  const pixel = new Uint8ClampedArray(4);
  return scaledProbe(width * height, () =>
    probePixels3d(width, height, (px, row) => renderPixel3d(frame, px, row, pixel, 0)),
  );
}

/** A volume render's cost: its seconds on one thread = rays × samples per ray × seconds per sample. */
export interface VolumeEstimate {
  readonly seconds: number;
  /** Mean samples a ray takes (those past the mirrors' ball take none, opaque ones stop early). */
  readonly samplesPerRay: number;
  /** Samples a ray is asked for (the `volume samples` setting). */
  readonly steps: number;
  /** One sample's time: the walk of its point and its compositing. */
  readonly secondsPerSample: number;
}

/**
 * Seconds a volume-rendered 3D render takes on one thread: the probe pixels' centre rays are
 * integrated by the renderer's own volumeRay, counting the samples each takes; the render has
 * width·height·spp rays. One sample's time is measured on the last quarter of the probe: the
 * first rays run while the walk is still being compiled (measured on Fig. 10: the first 16 rays
 * over ten times slower per sample than rays a thousand on), and the render itself runs warm.
 */
export function estimateVolume3d(
  scene: Scene3d,
  width: number,
  height: number,
  samples: number,
): VolumeEstimate {
  const volume = scene.volume;
  if (!volume) throw new Error('estimateVolume3d needs a volume-rendered scene');
  const f = render3dFrame(scene, width, height, { samples: 1 });
  /** Samples taken and the clock after each ray. */
  const taken: number[] = [0];
  const clock: number[] = [performance.now()];
  const rays = probePixels3d(width, height, (px, row) => {
    const py = height - 1 - row;
    const d = rayDirection(f.basis, width, height, px + 0.5, py + 0.5);
    const r = volumeRay(f.plan, f.volumeBounds, volume, f.basis.origin, d, volumeJitter(px, py));
    taken.push(taken.at(-1)! + r.samples);
    clock.push(performance.now());
  });
  const perSample = (from: number) => {
    const n = taken[rays]! - taken[from]!;
    return n > 0 ? (clock[rays]! - clock[from]!) / 1000 / n : null;
  };
  const secondsPerSample = perSample(Math.floor((3 * rays) / 4)) ?? perSample(0) ?? 0;
  const samplesPerRay = taken[rays]! / Math.max(1, rays);
  const seconds = width * height * Math.max(1, samples) * samplesPerRay * secondsPerSample;
  return { seconds, samplesPerRay, steps: volume.steps, secondsPerSample };
}

/**
 * A 3D render's single-thread seconds and how it is drawn, for the announcement: "sphere traced",
 * or "volume rendered, about 41 of 128 samples per ray".
 */
export function estimate3d(
  scene: Scene3d,
  width: number,
  height: number,
  samples: number,
): { readonly seconds: number; readonly how: string } {
  if (!scene.volume)
    return { seconds: estimateRender3dSeconds(scene, width, height, samples), how: 'sphere traced' };
  const v = estimateVolume3d(scene, width, height, samples);
  return {
    seconds: v.seconds,
    how: `volume rendered, about ${Math.round(v.samplesPerRay)} of ${v.steps} samples per ray`,
  };
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
