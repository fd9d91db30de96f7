/**
 * Compares a GPU probe image with the float64 CPU reference at the same pixel centres.
 *
 * Excluded: pixels whose path comes within ε of an element boundary, measured back in the
 * original coordinates (shader-gen/path-margin.ts), ε = 1e-5 × view scale. Why 1e-5: it is 1/400
 * of a pixel at 256² (so only thin lines along the boundaries' images drop out), yet ~170× the
 * float32 rounding of the sample point itself (2⁻²⁴ ≈ 6e-8 relative); the largest margin at which
 * float32 and float64 were seen to take different branches over all examples was 2.4e-6 × scale.
 *
 * Final points: a float32 run carries a rounding of about 2⁻²⁴·|p| per step, which later steps
 * stretch by the accumulated scale s; summed over the path this is bounded by
 * 2⁻²⁴ (depth + 1) ((|w| + view scale) s + |final|). Measured errors stay below 2.5× that bound;
 * the tolerance is 16× it.
 */
import type { Scene, SeedSpec } from '../../nodes/core/scene.ts';
import { pixelToWorld } from '../../nodes/core/view.ts';
import type { IisState } from '../../shader-gen/elements/element-kind.ts';
import { type PreparedElements, prepare, runIis } from '../../shader-gen/interpret.ts';
import { type MarginResult, pathMargin } from '../../shader-gen/path-margin.ts';
import { placeUv } from '../../shader-gen/placement.ts';
import { sampleColour, sampleContext } from '../../shader-gen/raster.ts';
import { seedAt, seedShapeValue } from '../../shader-gen/seeds.ts';
import { linearToSrgb } from '../../shader-gen/srgb.ts';
import type { ProbeImage } from './gpu-probe.ts';

export const MARGIN_FRACTION = 1e-5;
const EPS32 = 2 ** -24;
const FINAL_FACTOR = 16;

export interface ProbeSample {
  readonly depth: number;
  readonly x: number;
  readonly y: number;
  readonly escaped: boolean;
}

export const probeAt = (img: ProbeImage, px: number, py: number): ProbeSample => {
  const o = 4 * (py * img.width + px);
  return { depth: img.data[o], x: img.data[o + 1], y: img.data[o + 2], escaped: img.data[o + 3] > 0.5 };
};

export interface ParityStats {
  readonly pixels: number;
  /** Pixels whose path passes within ε of a boundary (not compared). */
  readonly excluded: number;
  readonly compared: number;
  readonly depthMismatch: number;
  readonly escapedMismatch: number;
  readonly finalMismatch: number;
  /** Compared pixels agreeing on depth, escaped and final point, as a fraction. */
  readonly agreement: number;
  /** Depth and escaped equal over ALL pixels, boundary pixels included. */
  readonly rawAgreement: number;
}

/** Whether two runs of the same sample point agree within the float32 error model above. */
export function samplesAgree(
  w: readonly [number, number],
  viewScale: number,
  ref: MarginResult,
  got: ProbeSample,
) {
  const depth = got.depth === ref.depth;
  const escaped = got.escaped === ref.escaped;
  const bound =
    EPS32 *
    (ref.depth + 1) *
    ((Math.hypot(w[0], w[1]) + viewScale) * ref.scale + Math.hypot(ref.final[0], ref.final[1]));
  const final = Math.hypot(got.x - ref.final[0], got.y - ref.final[1]) <= FINAL_FACTOR * bound;
  return { depth, escaped, final };
}

/** Where the compared image lies: the part at `offset` of an image of `resolution` pixels. */
export interface ImageFrame {
  readonly resolution: readonly [number, number];
  readonly offset: readonly [number, number];
}

export interface CompareOptions {
  /**
   * The least share of the image's pixels that must be compared (not excluded near a boundary).
   * Every caller states it: an agreement over next to no pixels proves nothing, so falling short
   * throws instead of reporting a vacuous 100 %.
   */
  readonly minCompared: number;
  /** The part of a bigger image that `img` is (default: the whole image). */
  readonly frame?: ImageFrame;
}

/** Throws when fewer than `minCompared` × pixels were compared (or minCompared is no share). */
export function assertEnoughCompared(what: string, compared: number, pixels: number, minCompared: number) {
  if (!(minCompared > 0 && minCompared <= 1))
    throw new Error(`${what}: minCompared must be a share in (0, 1], got ${minCompared}`);
  if (compared < minCompared * pixels)
    throw new Error(
      `${what}: only ${compared} of ${pixels} pixels were compared (${pixels - compared} lie near a boundary); at least ${Math.ceil(minCompared * pixels)} are needed`,
    );
}

/**
 * Compares `img` (rendered with `scene.view` at jitter 0.5, by default as the whole image) with
 * the CPU, pixel by pixel; throws unless at least `minCompared` of the pixels were compared.
 */
export function compareWithCpu(scene: Scene, img: ProbeImage, options: CompareOptions): ParityStats {
  const frame = options.frame;
  const [W, H] = frame?.resolution ?? [img.width, img.height];
  const [ox, oy] = frame?.offset ?? [0, 0];
  const prepared = prepare(scene.elements);
  const eps = MARGIN_FRACTION * scene.view.scale;
  let excluded = 0;
  let depthMismatch = 0;
  let escapedMismatch = 0;
  let finalMismatch = 0;
  let agree = 0;
  let rawAgree = 0;
  for (let py = 0; py < img.height; py++) {
    for (let px = 0; px < img.width; px++) {
      const w = pixelToWorld(scene.view, W, H, px + ox, py + oy);
      const ref = pathMargin(prepared, scene.maxIterations, w);
      const ok = samplesAgree(w, scene.view.scale, ref, probeAt(img, px, py));
      if (ok.depth && ok.escaped) rawAgree++;
      if (ref.margin < eps) {
        excluded++;
        continue;
      }
      if (!ok.depth) depthMismatch++;
      if (!ok.escaped) escapedMismatch++;
      if (!ok.final) finalMismatch++;
      if (ok.depth && ok.escaped && ok.final) agree++;
    }
  }
  const pixels = img.width * img.height;
  const compared = pixels - excluded;
  assertEnoughCompared('probe vs CPU', compared, pixels, options.minCompared);
  return {
    pixels,
    excluded,
    compared,
    depthMismatch,
    escapedMismatch,
    finalMismatch,
    agreement: agree / compared,
    rawAgreement: rawAgree / pixels,
  };
}

/** Two GPU images of the same scene (e.g. generated vs hand-written): same depth and escaped. */
export function compareImages(
  a: ProbeImage,
  b: ProbeImage,
): { pixels: number; same: number; agreement: number } {
  let same = 0;
  for (let py = 0; py < a.height; py++) {
    for (let px = 0; px < a.width; px++) {
      const s = probeAt(a, px, py);
      const t = probeAt(b, px, py);
      if (s.depth === t.depth && s.escaped === t.escaped) same++;
    }
  }
  const pixels = a.width * a.height;
  return { pixels, same, agreement: same / pixels };
}

/** Largest difference of an 8-bit sRGB channel accepted between the GPU and the CPU colour. */
export const COLOUR_LEVELS = 2;

export interface ColourStats {
  readonly pixels: number;
  readonly excluded: number;
  readonly compared: number;
  /** Largest channel difference seen, in 8-bit sRGB levels, over compared pixels. */
  readonly worstLevels: number;
  readonly agreement: number;
}

const level = (linear: number) => Math.round(linearToSrgb(Math.min(1, Math.max(0, linear))) * 255);

/** Distance from (x, y) to the edge of a seed (disk rim or picture rectangle), in world units. */
function seedEdgeDistance(seed: SeedSpec, x: number, y: number): number {
  if (seed.kind === 'disk') return Math.abs(Math.hypot(x - seed.c[0], y - seed.c[1]) - seed.r);
  if (seed.kind === 'shape') {
    // First order: |f| / |∇f| (central differences) estimates the distance to the zero set f = 0.
    const f = (px: number, py: number) => seedShapeValue(seed, px, py);
    const h = 1e-6 * Math.max(1, Math.abs(x), Math.abs(y));
    const gx = (f(x + h, y) - f(x - h, y)) / (2 * h);
    const gy = (f(x, y + h) - f(x, y - h)) / (2 * h);
    return Math.abs(f(x, y)) / Math.max(Math.hypot(gx, gy), 1e-12);
  }
  const [u, v] = placeUv(
    seed.center[0],
    seed.center[1],
    1,
    1,
    Math.cos(seed.rotation),
    Math.sin(seed.rotation),
    x,
    y,
  );
  // u, v here are the local coordinates + ½ (w = h = 1): distance to the rectangle's edge lines.
  const lx = Math.abs(u - 0.5);
  const ly = Math.abs(0.5 - v);
  return Math.min(Math.abs(lx - seed.width / 2), Math.abs(ly - seed.height / 2));
}

/**
 * How close a sample comes to a boundary of its colouring (besides the elements'): the seeds'
 * edges at every point of its path up to the seed that stops it, and the inner circle at the final
 * point, each divided by the scale s there (back in the original coordinates).
 */
function colourMargin(scene: Scene, prepared: PreparedElements, w: readonly [number, number]): number {
  const seeds = scene.tile.seeds ?? [];
  const inner = scene.tile.inner;
  if (seeds.length === 0 && !inner) return Number.POSITIVE_INFINITY;
  let margin = Number.POSITIVE_INFINITY;
  const st: IisState = { x: w[0], y: w[1], s: 1, depth: 0 };
  let stopped = false;
  runIis(prepared, scene.maxIterations, st, (at) => {
    for (const seed of seeds) margin = Math.min(margin, seedEdgeDistance(seed, at.x, at.y) / at.s);
    stopped = seedAt(seeds, at.x, at.y) >= 0;
    return stopped;
  });
  if (inner && !stopped)
    margin = Math.min(margin, Math.abs(Math.hypot(st.x - inner.c[0], st.y - inner.c[1]) - inner.r) / st.s);
  return margin;
}

/**
 * Compares a colour-variant image (linear RGBA, rendered at the pixel centres) with the CPU's
 * sampleColour, channel by channel in 8-bit sRGB; pixels whose path or sample point lies within ε
 * of a boundary (an element's, or the clip circle's) are excluded as in compareWithCpu; throws
 * unless at least `minCompared` of the pixels were compared.
 */
export function compareColourWithCpu(
  scene: Scene,
  img: ProbeImage,
  options: Omit<CompareOptions, 'frame'>,
): ColourStats {
  const ctx = sampleContext(scene);
  const prepared = ctx.prepared;
  const eps = MARGIN_FRACTION * scene.view.scale;
  const pixelWorld = scene.view.scale / img.height;
  const st: IisState = { x: 0, y: 0, s: 1, depth: 0 };
  let excluded = 0;
  let agree = 0;
  let worstLevels = 0;
  for (let py = 0; py < img.height; py++) {
    for (let px = 0; px < img.width; px++) {
      const w = pixelToWorld(scene.view, img.width, img.height, px, py);
      const clip = scene.clip;
      const clipMargin = clip ? Math.abs(Math.hypot(w[0] - clip.c[0], w[1] - clip.c[1]) - clip.r) : Infinity;
      if (
        clipMargin < eps ||
        pathMargin(prepared, scene.maxIterations, w).margin < eps ||
        colourMargin(scene, prepared, w) < eps
      ) {
        excluded++;
        continue;
      }
      const cpu = sampleColour(scene, ctx, w[0], w[1], pixelWorld, st);
      const o = 4 * (py * img.width + px);
      let worst = 0;
      for (let k = 0; k < 3; k++) worst = Math.max(worst, Math.abs(level(img.data[o + k]) - level(cpu[k])));
      worstLevels = Math.max(worstLevels, worst);
      if (worst <= COLOUR_LEVELS && img.data[o + 3] === 1) agree++;
    }
  }
  const pixels = img.width * img.height;
  const compared = pixels - excluded;
  assertEnoughCompared('colour vs CPU', compared, pixels, options.minCompared);
  return { pixels, excluded, compared, worstLevels, agreement: agree / compared };
}
