/**
 * Shading of a hit, in linear light (docs/math-3d.md "§9 The sphere tracer: march, hit, shading"), CPU twin of glsl/shade.glsl.ts:
 *   normal — tetrahedral central differences of the seed-image distance f (the walk's
 *            imageDistance) with step h = ε at the hit: n = normalize(Σ k_i f(p + h k_i)),
 *            k ∈ {(1,−1,−1), (−1,−1,1), (−1,1,−1), (1,1,1)};
 *   colour — Coloring3d (base, sRGB → linear);
 *   light  — Blinn–Phong: base·(ambient·ao + diffuse·max(n·L, 0)·sh) + specular·(n·H)^shininess·sh;
 *   ao     — 1 − occlusion·Σ_k w_k clamp((h_k − f(p + h_k n))/h_k, 0, 1), h_k = k·AO_STEP·size/factor,
 *            w_k = 2^−k normalised (size/factor: the seed image's own scale, so deep small spheres
 *            are shaded like big ones);
 *   shadow — a soft-shadow march towards the light on the safe DE: res = min(res, SHADOW_K·DE/t);
 *            sh = 1 − shadow·(1 − res).
 */

import type { Coloring3d, Scene3d } from '../../nodes/core/scene-3d.ts';
import type { Color } from '../../nodes/core/values.ts';
import { finiteValue } from '../../nodes/formula/checked.ts';
import { COLOUR_3D_NAMES } from '../../nodes/formula/names.ts';
import type { Vec3 } from '../../nodes/geometry/space/vec3.ts';
import { cosinePalette, hsvToRgb } from '../colour.ts';
import { type Rgb, toLinear } from '../srgb.ts';
import type { TracePlan } from './plan.ts';
import { seedSize } from './seeds-3d.ts';
import { type Hit3d, hitTolerance } from './trace-3d.ts';
import { walk3d } from './walk.ts';

export const AO_SAMPLES = 4;
export const AO_STEP = 0.15;
export const SHADOW_STEPS = 24;
export const SHADOW_K = 8;
const TETRA: readonly Vec3[] = [
  [1, -1, -1],
  [-1, -1, 1],
  [-1, 1, -1],
  [1, 1, 1],
];

const fract = (v: number) => v - Math.floor(v);
const clamp01 = (v: number) => Math.min(1, Math.max(0, v));

/** RGB (sRGB, [0,1]) → HSV with the hue in turns: the inverse of colour.ts hsvToRgb. */
export function rgbToHsv(c: Color): [number, number, number] {
  const [r, g, b] = c;
  const max = Math.max(r, g, b);
  const min = Math.min(r, g, b);
  const delta = max - min;
  let h = 0;
  if (delta > 0) {
    if (max === r) h = (g - b) / delta / 6;
    else if (max === g) h = ((b - r) / delta + 2) / 6;
    else h = ((r - g) / delta + 4) / 6;
  }
  return [fract(h), max > 0 ? delta / max : 0, max];
}

/** The cosine field 0.5 + 0.5 cos(2π p_k/scale) per channel (surface and final-point colourings). */
const field = (p: Vec3, scale: number): Rgb =>
  [0, 1, 2].map((k) => 0.5 + 0.5 * Math.cos((2 * Math.PI * p[k]!) / scale)) as Rgb;

/** A measured colouring of Coloring3d: by distance from the origin, by argument, or by a formula. */
export type MeasureColoring3d = Extract<Coloring3d, { mode: 'distance' | 'argument' | 'formula' }>;

/** The measure m of the point p: |p| (distance), or atan2(p_y, p_x)/2π turns in (−½, ½] (argument). */
export function measure3d(mode: 'distance' | 'argument', p: Vec3): number {
  return mode === 'distance' ? Math.hypot(p[0], p[1], p[2]) : Math.atan2(p[1], p[0]) / (2 * Math.PI);
}

/** One scratch environment for 3D colour formulas (each renderer thread has its own module). */
const colourEnv = { x: 0, y: 0, z: 0, n: 0 };

/**
 * The `formula` measure: the render's colour function of the hit point's x, y, z and the depth n
 * (docs/formula.md "Colour functions"); 0 where it is not a finite number, as in the GLSL twin.
 */
export function colourFormula3d(text: string, p: Vec3, depth: number): number {
  colourEnv.x = p[0];
  colourEnv.y = p[1];
  colourEnv.z = p[2];
  colourEnv.n = depth;
  return finiteValue(text, COLOUR_3D_NAMES, colourEnv);
}

/**
 * The palette colour at t = offset + frequency·m (sRGB): the seed colour's hue turned by t turns
 * (wheel), else the cosine palette a + b·cos(2π(c·t + d)).
 */
export function measureColour3d(coloring: MeasureColoring3d, seedColour: Color, p: Vec3, depth = 0): Rgb {
  const m =
    coloring.mode === 'formula'
      ? colourFormula3d(coloring.formula ?? '0', p, depth)
      : measure3d(coloring.mode, p);
  const t = coloring.offset + coloring.frequency * m;
  if (!coloring.wheel) return cosinePalette(coloring.a, coloring.b, coloring.c, coloring.d, t);
  const [h, s, v] = rgbToHsv(seedColour);
  return hsvToRgb(h + t, s, v);
}

/**
 * The hit's base colour in sRGB (`point`: the hit on the surface; `final`: where its IIS ends).
 * The measured colourings read the hit point: neighbouring pixels of a quasi-sphere end their
 * walks on unrelated copies, so a final-point measure is noise until many samples average it
 * (docs/math-3d.md §9 "Colour").
 */
export function baseColour(
  coloring: Coloring3d,
  seedColour: Color,
  depth: number,
  point: Vec3,
  final: Vec3,
): Rgb {
  switch (coloring.mode) {
    case 'depth-wheel': {
      const [h, s, v] = rgbToHsv(seedColour);
      return hsvToRgb(h + coloring.step * depth, s, v);
    }
    case 'cosine':
      return cosinePalette(coloring.a, coloring.b, coloring.c, coloring.d, depth * coloring.step);
    case 'surface':
      return field(point, coloring.scale);
    case 'final-point':
      return field(final, coloring.scale);
    case 'distance':
    case 'argument':
    case 'formula':
      return measureColour3d(coloring, seedColour, point, depth);
  }
}

const normalize = (v: Vec3): Vec3 => {
  const l = Math.hypot(v[0], v[1], v[2]) || 1;
  return [v[0] / l, v[1] / l, v[2] / l];
};
const at = (p: Vec3, d: Vec3, t: number): Vec3 => [p[0] + d[0] * t, p[1] + d[1] * t, p[2] + d[2] * t];
const dot = (a: Vec3, b: Vec3) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
const f = (plan: TracePlan, p: Vec3) => walk3d(plan, p[0], p[1], p[2], false).imageDistance;

/** Where a hit is: the point, its unit normal, its base colour (linear) and the tolerance ε there. */
export interface Surface3d {
  readonly p: Vec3;
  readonly n: Vec3;
  readonly base: Rgb;
  readonly eps: number;
}

/** The surface at the hit `h` of the ray o + t·d (angle per pixel `angle`). */
export function surfaceAt(plan: TracePlan, o: Vec3, d: Vec3, angle: number, h: Hit3d): Surface3d {
  const p = at(o, d, h.t);
  const eps = hitTolerance(plan, angle, h.t);
  let g: Vec3 = [0, 0, 0];
  for (const k of TETRA) g = at(g, k, f(plan, at(p, k, eps)));
  const seed = plan.scene.seeds[h.seed]!;
  const base = toLinear(baseColour(plan.scene.coloring, seed.color, h.depth, p, h.final));
  return { p, n: normalize(g), base, eps };
}

/** Linear colour of the hit `h` of the ray o + t·d (angle per pixel `angle`), lit matte. */
export function shadeHit(
  plan: TracePlan,
  o: Vec3,
  d: Vec3,
  angle: number,
  h: Hit3d,
  surface: Surface3d = surfaceAt(plan, o, d, angle, h),
): Rgb {
  const scene: Scene3d = plan.scene;
  const light = scene.lighting;
  const { p, n, base, eps } = surface;
  const seed = scene.seeds[h.seed]!;
  const l = normalize(light.direction);
  const diff = Math.max(dot(n, l), 0);
  const half = normalize([l[0] - d[0], l[1] - d[1], l[2] - d[2]]);
  const spec = diff > 0 ? Math.max(dot(n, half), 0) ** light.shininess : 0;
  // Ambient occlusion on the seed image's own scale.
  const aoStep = Math.max((AO_STEP * seedSize(seed)) / h.factor, eps);
  let occ = 0;
  let weights = 0;
  for (let k = 1; k <= AO_SAMPLES; k++) {
    const hk = k * aoStep;
    const w = 0.5 ** k;
    occ += w * clamp01((hk - f(plan, at(p, n, hk))) / hk);
    weights += w;
  }
  const ao = 1 - light.occlusion * (occ / weights);
  // Soft shadow: march towards the light from just off the surface.
  let res = 1;
  if (light.shadow > 0 && diff > 0) {
    const from = at(p, n, 2 * eps);
    let t = 2 * eps;
    for (let i = 0; i < SHADOW_STEPS; i++) {
      const q = at(from, l, t);
      const w = walk3d(plan, q[0], q[1], q[2], true);
      const e = hitTolerance(plan, angle, h.t + t);
      if (w.imageDistance < e) {
        res = 0;
        break;
      }
      res = Math.min(res, (SHADOW_K * w.de) / t);
      t += Math.max(scene.deScale * w.de, e);
      if (t > 2 * plan.bounds.radius) break;
    }
  }
  const sh = 1 - light.shadow * (1 - clamp01(res));
  const lit = light.ambient * ao + light.diffuse * diff * sh;
  const hi = light.specular * spec * sh;
  return [base[0] * lit + hi, base[1] * lit + hi, base[2] * lit + hi];
}
