/**
 * The vector picture of a scene: the images of its tile edges (the element boundaries) and of its
 * seed disks under the group, enumerated in float64 on the CPU down to a size cutoff. Shared by the
 * `kleinflow svg` command and the editor's "Export SVG…". Pure: no DOM.
 *
 * An edge of depth n bounds a tile reached in n steps: the tile at depth n inside element e is
 * step_e⁻¹(tile at depth n−1), so its edges are step_e⁻¹ of the edges one level up (docs/math.md,
 * "The IIS loop"). Every step here is a chain of mirrors (inversion / reflection), so step⁻¹ is the
 * same chain reversed and maps circles and lines to circles and lines (curves.ts).
 */
import type { Scene, SceneElement } from '../../nodes/core/scene.ts';
import type { Circle, Color } from '../../nodes/core/values.ts';
import { type Curve, imageUnder, type Mirror, meetsRegion, type Region } from './curves.ts';

/**
 * Curves closer than this many output pixels count as one. Graphs built from rounded coordinates
 * are only nearly discrete groups: the same edge reached by two words differs by rounding, which
 * grows with the word length.
 */
const DUPLICATE_PX = 0.01;

/** The most elements one export writes: beyond it the file is too big for any viewer to use. */
export const MAX_VECTOR_ELEMENTS = 200_000;

export interface VectorOptions {
  readonly width: number;
  readonly height: number;
  /** Smallest radius written (and expanded further), in output pixels. */
  readonly minRadius: number;
  /** Element cap (default MAX_VECTOR_ELEMENTS). */
  readonly maxElements?: number;
}

export interface VectorCurve {
  readonly curve: Curve;
  /** Steps from the fundamental tile (0: its own edge). */
  readonly depth: number;
}

export interface VectorSeed extends VectorCurve {
  readonly color: Color;
}

export type VectorPicture =
  | { readonly ok: true; readonly edges: readonly VectorCurve[]; readonly seeds: readonly VectorSeed[] }
  | { readonly ok: false; readonly message: string; readonly nodeId?: string };

/** One inverse step: the mirrors applied in order, and the index of the generator that undoes it. */
interface Generator {
  readonly mirrors: readonly Mirror[];
  inverse: number;
  /**
   * The element's inside, where this inverse step puts the tiles it makes: an image that misses it
   * walks back towards the fundamental tile (a word that undoes itself) and is not followed.
   */
  readonly region: Region;
}

interface ElementParts {
  readonly boundaries: readonly Curve[];
  readonly generators: readonly Generator[];
}

const circle = (c: { c: readonly [number, number]; r: number }): Curve => ({
  kind: 'circle',
  c: [...c.c],
  r: c.r,
});

/** The boundaries and inverse steps of one element, or null when its step is not made of mirrors. */
function elementParts(e: SceneElement, base: number): ElementParts | null {
  switch (e.kind) {
    case 'inversion': {
      const m = circle(e);
      const region: Region = { kind: 'disk', c: [...e.c], r: e.r, outside: false };
      return { boundaries: [m], generators: [{ mirrors: [m], inverse: base, region }] };
    }
    case 'reflection': {
      const m: Mirror = { kind: 'line', q: [...e.q], n: [...e.n] };
      const region: Region = { kind: 'half-plane', q: [...e.q], n: [...e.n] };
      return { boundaries: [m], generators: [{ mirrors: [m], inverse: base, region }] };
    }
    case 'mobius': {
      // In A the step is σ_C2∘σ_C1 (σ_C1 first), so its inverse applies σ_C2 then σ_C1; in B the reverse.
      const c1 = circle(e.c1);
      const c2 = circle(e.c2);
      return {
        boundaries: [circle(e.a), circle(e.b)],
        generators: [
          { mirrors: [c2, c1], inverse: base + 1, region: { kind: 'disk', ...e.a } },
          { mirrors: [c1, c2], inverse: base, region: { kind: 'disk', ...e.b } },
        ],
      };
    }
    default:
      return null;
  }
}

const KIND_NAMES: Partial<Record<SceneElement['kind'], string>> = {
  loxodromic: 'a loxodromic generator (three mirrors and a line, with a twist)',
  'mobius-matrix': 'a Möbius matrix generator',
  translation: 'a translation fold',
  'parallel-mirrors': 'a parallel-mirrors fold',
  'glide-reflection': 'a glide-reflection fold',
  rotation: 'a rotation fold',
  'spiral-similarity': 'a spiral similarity',
  maskit: 'a Maskit group',
  'maskit-slice': 'the Maskit slice (a picture of parameters, not of a group)',
};

/** A key equal for curves that agree to `eps` (world units): the enumeration's duplicate test. */
function curveKey(k: Curve, eps: number, far: number): string {
  const q = (v: number) => Math.round(v / eps);
  if (k.kind === 'circle') return `c${q(k.c[0])},${q(k.c[1])},${q(k.r)}`;
  // Orient n so the key does not depend on which side the normal points to.
  const flip = k.n[0] < 0 || (k.n[0] === 0 && k.n[1] < 0) ? -1 : 1;
  const nx = k.n[0] * flip;
  const ny = k.n[1] * flip;
  // A direction error δ moves the line by δ·far at the edge of the region kept.
  const dq = (v: number) => Math.round((v * far) / eps);
  return `l${dq(nx)},${dq(ny)},${q(k.q[0] * nx + k.q[1] * ny)}`;
}

interface OrbitBounds {
  readonly maxDepth: number;
  /** World units. */
  readonly minRadius: number;
  /** Duplicate tolerance, world units. */
  readonly eps: number;
  readonly centre: readonly [number, number];
  /** World distance from the view centre beyond which a line or an outside circle is dropped. */
  readonly far: number;
  readonly clip: Circle | null;
}

/**
 * Whether the curve stays outside the clip disk (wholly outside it, or around it): nothing of it
 * shows. It is not expanded either: a clip disk is the disk the group keeps (the Poincaré disk),
 * whose outside the group maps to itself, and expanding the outside there (images accumulating on
 * the clip circle from outside, mirror centres beyond it) only costs time.
 */
function missesClip(k: Curve, clip: Circle | null): boolean {
  if (!clip) return false;
  if (k.kind === 'line') return curveDistance(k, clip.c) >= clip.r;
  const d = Math.hypot(k.c[0] - clip.c[0], k.c[1] - clip.c[1]);
  return d >= k.r + clip.r || d + clip.r <= k.r;
}

/**
 * Whether the curve lies farther than bounds.far from the view centre without enclosing it. A
 * Euclidean group (mirrors that are lines) has images that never shrink: distance is what bounds
 * its enumeration. Isometries move a curve by at most twice the mirrors' distance from the view,
 * which `far` allows for.
 */
function isFar(k: Curve, b: OrbitBounds): boolean {
  if (k.kind === 'line') {
    return Math.abs((b.centre[0] - k.q[0]) * k.n[0] + (b.centre[1] - k.q[1]) * k.n[1]) > b.far;
  }
  return Math.hypot(k.c[0] - b.centre[0], k.c[1] - b.centre[1]) - k.r > b.far;
}

/** Distance from p to the curve. */
function curveDistance(k: Curve, p: readonly [number, number]): number {
  if (k.kind === 'line') return Math.abs((p[0] - k.q[0]) * k.n[0] + (p[1] - k.q[1]) * k.n[1]);
  return Math.abs(Math.hypot(k.c[0] - p[0], k.c[1] - p[1]) - k.r);
}

/**
 * Breadth-first images of `start` under the generators up to maxDepth steps. An image is followed
 * only when it reaches into its generator's region (Generator.region: the word does not walk back)
 * and is not a duplicate; circles under minRadius world units are dropped with their images (a
 * mirror shrinks what it maps inside it). Returns null when more than `cap` curves are found.
 */
function orbit(
  start: readonly Curve[],
  generators: readonly Generator[],
  bounds: OrbitBounds,
  cap: number,
): VectorCurve[] | null {
  const { maxDepth, minRadius, eps } = bounds;
  const tol = eps * 10;
  const seen = new Set<string>();
  const out: VectorCurve[] = [];
  let level: { curve: Curve; depth: number; last: number }[] = [];
  const visit = (curve: Curve, depth: number, last: number): boolean => {
    if (curve.kind === 'circle' && !(curve.r >= minRadius)) return true;
    if (curve.kind === 'circle' && !Number.isFinite(curve.r)) return true;
    if (isFar(curve, bounds) || missesClip(curve, bounds.clip)) return true;
    const key = curveKey(curve, eps, bounds.far);
    if (seen.has(key)) return true;
    seen.add(key);
    out.push({ curve, depth });
    level.push({ curve, depth, last });
    return out.length <= cap;
  };
  for (const k of start) if (!visit(k, 0, -1)) return null;
  for (let depth = 1; depth <= maxDepth && level.length > 0; depth++) {
    const previous = level;
    level = [];
    for (const item of previous) {
      for (let g = 0; g < generators.length; g++) {
        if (item.last >= 0 && generators[item.last].inverse === g) continue;
        const image = imageUnder(generators[g].mirrors, item.curve);
        if (!meetsRegion(image, generators[g].region, tol)) continue;
        if (!visit(image, depth, g)) return null;
      }
    }
  }
  return out;
}

/** The scene's tile edges and seed disks as curves, or why it has no vector picture. */
export function vectorPicture(scene: Scene, options: VectorOptions): VectorPicture {
  const cap = options.maxElements ?? MAX_VECTOR_ELEMENTS;
  const boundaries: Curve[] = [];
  const generators: Generator[] = [];
  for (const e of scene.elements) {
    const parts = elementParts(e, generators.length);
    if (!parts) {
      return {
        ok: false,
        nodeId: e.nodeId,
        message: `node "${e.nodeId}" is ${KIND_NAMES[e.kind] ?? e.kind}: its images are not circles and lines, so the picture has no vector form (export a PNG instead)`,
      };
    }
    boundaries.push(...parts.boundaries);
    generators.push(...parts.generators);
  }
  const worldPerPixel = scene.view.scale / options.height;
  const tooMany = {
    ok: false as const,
    message: `more than ${cap} circles and lines are at least ${options.minRadius} px in radius: raise the minimum radius`,
  };
  const centre = scene.view.center;
  const halfDiagonal = (worldPerPixel * Math.hypot(options.width, options.height)) / 2;
  const mirrorReach = Math.max(0, ...boundaries.map((k) => curveDistance(k, centre)));
  const bounds: OrbitBounds = {
    maxDepth: scene.maxIterations,
    minRadius: options.minRadius * worldPerPixel,
    eps: worldPerPixel * DUPLICATE_PX,
    centre,
    far: 2 * (halfDiagonal + 2 * mirrorReach),
    clip: scene.clip,
  };
  const edges = orbit(boundaries, generators, bounds, cap);
  if (!edges) return tooMany;
  const seeds: VectorSeed[] = [];
  for (const s of scene.tile.seeds ?? []) {
    if (s.kind !== 'disk') {
      const what =
        s.kind === 'image'
          ? 'a seed picture: its images are pictures'
          : 'a seed shape: its images are curved regions';
      return {
        ok: false,
        nodeId: s.nodeId,
        message: `node "${s.nodeId}" is ${what}, not circles and lines, so the picture has no vector form (export a PNG instead)`,
      };
    }
    const images = orbit([{ kind: 'circle', c: [...s.c], r: s.r }], generators, bounds, cap);
    if (!images || edges.length + seeds.length + images.length > cap) return tooMany;
    for (const im of images) seeds.push({ ...im, color: s.color });
  }
  return { ok: true, edges, seeds };
}
