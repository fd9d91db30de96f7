/**
 * Hand-made scenes for the compiler tests (golden sources, glslang, parity of the element kinds
 * the examples do not use). Built directly as Scene values, so they stay the same whatever the
 * node types do; every element kind and every colouring mode appears.
 */
import {
  type Coloring,
  DEFAULT_TILE,
  type Measure,
  type Scene,
  type SceneElement,
  type SeedSpec,
  type TileSpec,
} from '../../../nodes/core/scene.ts';
import { BUILTIN_PICTURE, type Circle, type Vec2 } from '../../../nodes/core/values.ts';
import { twoCircleRegions } from '../../../nodes/geometry/mobius.ts';

export const COLORINGS: Readonly<Record<Coloring['mode'], Coloring>> = {
  'depth-hsv': { mode: 'depth-hsv', hueOffset: 0.01, hueStep: 0.05, saturation: 0.8, value: 0.95 },
  cosine: DEFAULT_TILE.coloring,
  parity: { mode: 'parity', even: [0.93, 0.91, 0.85], odd: [0.13, 0.16, 0.24] },
  image: { mode: 'image', image: BUILTIN_PICTURE, center: [0.45, 0.3], size: 0.9, rotation: 0.3 },
  'limit-set': { mode: 'limit-set', glow: 4 },
  measure: {
    mode: 'measure',
    measure: 'argument',
    a: [0.5, 0.5, 0.5],
    b: [0.5, 0.5, 0.5],
    c: [1, 1, 1],
    d: [0, 0.1, 0.2],
    scale: 1,
    offset: 0.1,
    trap: { c: [0.4, -0.3], r: 0.25 },
  },
};

/** The measure colouring reading `measure`, scaled by `scale`. */
export const measureColoring = (measure: Measure, scale = 1): Coloring => ({
  ...(COLORINGS.measure as Extract<Coloring, { mode: 'measure' }>),
  measure,
  scale,
});

export interface SceneOptions {
  readonly coloring?: Coloring;
  readonly edgeWidth?: number;
  readonly clip?: Circle | null;
  readonly maxIterations?: number;
  readonly center?: Vec2;
  readonly scale?: number;
  /** Tile options beyond the colouring (fill, seeds, seedsOnly, inner). */
  readonly tile?: Partial<TileSpec>;
}

export function makeScene(elements: readonly SceneElement[], o: SceneOptions = {}): Scene {
  // Every value spelled out (not DEFAULT_TILE), so the golden sources do not move with defaults.
  const tile: TileSpec = {
    nodeId: 'tile',
    coloring: o.coloring ?? COLORINGS.cosine,
    limitColor: [0.02, 0.02, 0.03],
    background: [0.06, 0.06, 0.08],
    edgeWidth: o.edgeWidth ?? 0,
    edgeColor: [1, 0.95, 0.8],
    ...o.tile,
  };
  return {
    elements,
    tile,
    maxIterations: o.maxIterations ?? 100,
    samples: 4,
    clip: o.clip ?? null,
    view: { center: o.center ?? [0, 0], scale: o.scale ?? 4 },
    overlays: [],
    handles: [],
    renderNodeId: 'out',
  };
}

export const reflection = (nodeId: string, q: Vec2, n: Vec2): SceneElement => ({
  kind: 'reflection',
  nodeId,
  q,
  n,
});
export const inversion = (nodeId: string, c: Vec2, r: number): SceneElement => ({
  kind: 'inversion',
  nodeId,
  c,
  r,
});

/**
 * A spherical kaleidoscope: two line mirrors through the origin at π/3 and the unit circle kept
 * from inside (outer inversion), which meets both at π/2 — the (2,2,3) group, tile = the wedge's
 * part of the unit disk.
 */
export const SPHERICAL_WEDGE: SceneElement[] = [
  reflection('w1', [0, 0], [0, 1]),
  reflection('w2', [0, 0], [Math.sin(Math.PI / 3), -Math.cos(Math.PI / 3)]),
  { kind: 'outer-inversion', nodeId: 'disk', c: [0, 0], r: 1 },
];

/** The two-circle generator σ_C2∘σ_C1 with its regions from nodes/geometry (docs/math.md). */
export function mobius(nodeId: string, c1: Circle, c2: Circle): SceneElement {
  const regions = twoCircleRegions(c1, c2);
  if (!regions.ok) throw new Error(regions.reason);
  return { kind: 'mobius', nodeId, c1, c2, a: regions.a, b: regions.b };
}

/** The (3,3,3) triangle: the *333 kaleidoscope (equilateral, side 1 at the origin). */
export const TRIANGLE_333: SceneElement[] = [
  reflection('m1', [0, 0], [0, 1]),
  reflection('m2', [0, 0], [Math.sin(Math.PI / 3), -Math.cos(Math.PI / 3)]),
  reflection('m3', [1, 0], [-Math.sin(Math.PI / 3), -Math.cos(Math.PI / 3)]),
];

/** A Schottky pair (classical: C1 and C1' disjoint) and one extra inversion circle. */
export const SCHOTTKY: SceneElement[] = [
  mobius('g', { c: [-1, 0], r: 0.6 }, { c: [0.2, 0.1], r: 1.0 }),
  inversion('i', [0, 1.6], 0.5),
];

/** Wallpaper of parallel mirrors (horizontal) and a translation (vertical lines of the strip). */
export const STRIPS: SceneElement[] = [
  { kind: 'parallel-mirrors', nodeId: 'pm', q: [0, -0.25], n: [0, 1], period: 0.5 },
  { kind: 'translation', nodeId: 'tr', q: [-0.35, 0], n: [1, 0], period: 0.7 },
];

/** A frieze: one glide reflection along the x axis. */
export const GLIDE: SceneElement[] = [
  { kind: 'glide-reflection', nodeId: 'gl', q: [0, 0], n: [1, 0], period: 0.8 },
];

/** Rotation of order 5 and a spiral similarity about the same centre: a rose of annular wedges. */
export const ROSE: SceneElement[] = [
  { kind: 'rotation', nodeId: 'rot', c: [0.05, -0.03], b1: [Math.cos(0.2), Math.sin(0.2)], order: 5 },
  { kind: 'spiral-similarity', nodeId: 'sp', c: [0.05, -0.03], r1: 0.35, r2: 0.5, angle: 0.25 },
];

/**
 * g(z) = (2z + 1)/(z + 1) (det 1, trace 3: hyperbolic): I(g) centre −d/c = −1, I(g⁻¹) centre
 * a/c = 2, both radius 1/|c| = 1, disjoint; the Ford domain is outside both.
 */
export const MATRIX: SceneElement[] = [
  {
    kind: 'mobius-matrix',
    nodeId: 'mm',
    a: [2, 0],
    b: [1, 0],
    c: [1, 0],
    d: [1, 0],
    forward: { c: [-1, 0], r: 1, outside: false },
    backward: { c: [2, 0], r: 1, outside: false },
  },
];

/** A loxodromic element with made-up but well-formed data (for code generation only). */
export const LOXODROMIC: SceneElement[] = [
  {
    kind: 'loxodromic',
    nodeId: 'lx',
    c1: { c: [0.1, 0], r: 0.5 },
    c2: { c: [0, 0], r: 2 },
    c3: { c: [0.3, 1.2], r: 1.1 },
    lq: [0, 0],
    ln: [0, 1],
    a: { c: [0.1, 0], r: 0.5, outside: false },
    b: { c: [-0.02, 0], r: 1.6, outside: true },
  },
];

/** The Maskit group at the cusp μ = 2i (its isometric circles tangent: an exact Ford domain). */
export const MASKIT_2I: SceneElement[] = [{ kind: 'maskit', nodeId: 'mk', mu: [0, 2] }];
/** Near the 2/5 cusp: the circles overlap, so the step's choice changes along a line (lens). */
export const MASKIT_CUSP: SceneElement[] = [{ kind: 'maskit', nodeId: 'mk', mu: [0.766588, 1.642139] }];

/** The Maskit slice in the parameter plane, its boundary through the cusps with q ≤ 24 (and ≤ 5). */
export const MASKIT_SLICE: SceneElement[] = [{ kind: 'maskit-slice', nodeId: 'ms', maxDenominator: 24 }];
export const MASKIT_SLICE_COARSE: SceneElement[] = [
  { kind: 'maskit-slice', nodeId: 'ms', maxDenominator: 5 },
];

/** Every element kind at least once, in one scene. */
export const EVERY_KIND: SceneElement[] = [
  ...TRIANGLE_333,
  ...SCHOTTKY,
  ...STRIPS,
  ...GLIDE,
  ...ROSE,
  ...MATRIX,
  ...LOXODROMIC,
  ...SPHERICAL_WEDGE,
  ...MASKIT_2I,
  ...MASKIT_SLICE_COARSE,
];

/** A disk seed and a picture seed outside the Schottky circles (both inside the tile). */
export const SEED_DISK: SeedSpec = {
  kind: 'disk',
  nodeId: 'sd',
  c: [1.5, -0.8],
  r: 0.3,
  color: [1, 0.8, 0.2],
};
export const SEED_PICTURE: SeedSpec = {
  kind: 'image',
  nodeId: 'sp',
  center: [-1.4, 1.3],
  width: 0.6,
  height: 0.45,
  rotation: 0.4,
  image: BUILTIN_PICTURE,
};

/** Seed shapes (formulas): a flower round p, and a turned box joined with a disk written with ** and pow. */
export const SEED_FLOWER: SeedSpec = {
  kind: 'shape',
  nodeId: 'sf',
  formula: 'length(z - p) - a * (1 + c * cos(b * atan2(y - p.y, x - p.x)))',
  numbers: [0.32, 5, 0.35, 0],
  points: [1.5, -0.8, 0, 0],
  color: [1, 0.5, 0.7],
};
export const SEED_BOX_SHAPE: SeedSpec = {
  kind: 'shape',
  nodeId: 'sb',
  formula:
    'min(max(abs(rotate(z - q, t).x) - a, abs(rotate(z - q, t).y) - b), (x - q.x - 0.3) ** 2 + pow(y - q.y, 2) - c * c)',
  numbers: [0.3, 0.15, 0.12, 0.4],
  points: [0, 0, -1.4, 1.3],
  color: [0.3, 0.9, 0.6],
};

/** Named hand-made scenes covering every element kind, colouring mode, edges and clip. */
export const HAND_MADE_SCENES: Readonly<Record<string, Scene>> = {
  'triangle-333-parity-clip': makeScene(TRIANGLE_333, {
    coloring: COLORINGS.parity,
    clip: { c: [0.5, 0.3], r: 1.5 },
    scale: 3,
  }),
  'schottky-cosine-edges': makeScene(SCHOTTKY, { edgeWidth: 1.5, maxIterations: 60, scale: 5 }),
  'strips-hsv-edges': makeScene(STRIPS, { coloring: COLORINGS['depth-hsv'], edgeWidth: 2, scale: 3 }),
  'glide-parity': makeScene(GLIDE, { coloring: COLORINGS.parity, scale: 3 }),
  'rose-cosine': makeScene(ROSE, { scale: 2.5, maxIterations: 200 }),
  'matrix-hsv-edges-clip': makeScene(MATRIX, {
    coloring: COLORINGS['depth-hsv'],
    edgeWidth: 1,
    clip: { c: [0.5, 0], r: 4 },
    scale: 7,
  }),
  'loxodromic-parity-edges': makeScene(LOXODROMIC, { coloring: COLORINGS.parity, edgeWidth: 1 }),
  'spherical-wedge-parity-edges': makeScene(SPHERICAL_WEDGE, {
    coloring: COLORINGS.parity,
    edgeWidth: 1.5,
    scale: 3,
  }),
  'every-kind-cosine-edges-clip': makeScene(EVERY_KIND, { edgeWidth: 1, clip: { c: [0, 0], r: 3 } }),
  empty: makeScene([]),
  // Tile options (colour.ts shade): fill, orbit seeds, seeds only, picture, limit set, inner area.
  'schottky-seeds-fill-edges': makeScene(SCHOTTKY, {
    edgeWidth: 1,
    maxIterations: 60,
    scale: 5,
    tile: { fill: [0, 0, 0], seeds: [SEED_DISK, SEED_PICTURE] },
  }),
  'schottky-seed-shapes': makeScene(SCHOTTKY, {
    maxIterations: 60,
    scale: 5,
    tile: { seeds: [SEED_FLOWER, SEED_BOX_SHAPE] },
  }),
  'schottky-seeds-only': makeScene(SCHOTTKY, {
    maxIterations: 60,
    scale: 5,
    tile: { seeds: [SEED_DISK], seedsOnly: true, seedFade: 0.15 },
  }),
  'triangle-333-picture': makeScene(TRIANGLE_333, {
    coloring: COLORINGS.image,
    scale: 3,
    center: [0.5, 0.3],
  }),
  'schottky-picture-fill': makeScene(SCHOTTKY, {
    coloring: { ...COLORINGS.image, center: [0, 0], size: 3 } as Coloring,
    maxIterations: 60,
    scale: 5,
    tile: { fill: [0.1, 0.1, 0.1] },
  }),
  'schottky-limit-set-glow': makeScene(SCHOTTKY, {
    coloring: COLORINGS['limit-set'],
    maxIterations: 40,
    scale: 5,
  }),
  'schottky-limit-set': makeScene(SCHOTTKY, {
    coloring: { mode: 'limit-set', glow: 0 },
    maxIterations: 40,
    scale: 5,
  }),
  'schottky-inner-parity': makeScene(SCHOTTKY, {
    coloring: COLORINGS.parity,
    maxIterations: 60,
    scale: 5,
    tile: { inner: { c: [0.3, -0.2], r: 1.2 } },
  }),
  // Measure colourings (colour.ts measureValue): the final point, edge distance, speed, trap.
  'schottky-argument': makeScene(SCHOTTKY, { coloring: COLORINGS.measure, maxIterations: 60, scale: 5 }),
  'triangle-333-final-x-edges': makeScene(TRIANGLE_333, {
    coloring: measureColoring('x', 0.8),
    edgeWidth: 1,
    scale: 3,
  }),
  'strips-final-y': makeScene(STRIPS, { coloring: measureColoring('y', 2), scale: 3 }),
  'rose-final-radius': makeScene(ROSE, {
    coloring: measureColoring('radius', 3),
    scale: 2.5,
    maxIterations: 200,
  }),
  'schottky-edge-distance': makeScene(SCHOTTKY, {
    coloring: measureColoring('edge', 2),
    maxIterations: 60,
    scale: 5,
  }),
  'matrix-escape-speed': makeScene(MATRIX, { coloring: measureColoring('speed', 0.15), scale: 7 }),
  'schottky-orbit-trap-seeds': makeScene(SCHOTTKY, {
    coloring: measureColoring('trap', 1.5),
    maxIterations: 60,
    scale: 5,
    tile: { seeds: [SEED_DISK] },
  }),
  'triangle-333-orbit-trap': makeScene(TRIANGLE_333, { coloring: measureColoring('trap', 2), scale: 3 }),
  // A colour function (docs/formula.md "Colour functions"): depth, scale and the final point at once.
  'schottky-colour-formula': makeScene(SCHOTTKY, {
    coloring: {
      ...(measureColoring('formula', 0.5) as object),
      formula: 'n / 4 + 0.3 * sin(3 * atan2(y, x)) + log(s) / 8',
    } as Coloring,
    maxIterations: 60,
    scale: 5,
  }),
  // The Maskit group (shader-gen/elements/maskit.ts), exact and with overlapping circles.
  'maskit-2i-cosine-edges': makeScene(MASKIT_2I, {
    edgeWidth: 1,
    maxIterations: 200,
    center: [0.3, 1],
    scale: 3,
  }),
  'maskit-cusp-hsv': makeScene(MASKIT_CUSP, {
    coloring: COLORINGS['depth-hsv'],
    maxIterations: 200,
    center: [0, 0.8],
    scale: 2.5,
  }),
  // The Maskit slice (shader-gen/elements/maskit-slice.ts): the verdict, its edge and its glow.
  'maskit-slice-edges': makeScene(MASKIT_SLICE, { edgeWidth: 1.5, center: [0, 1.5], scale: 4.3 }),
  'maskit-slice-limit-set': makeScene(MASKIT_SLICE_COARSE, {
    coloring: COLORINGS['limit-set'],
    center: [0.4, 1.7],
    scale: 1.2,
  }),
  'maskit-cusp-limit-set': makeScene(MASKIT_CUSP, {
    coloring: COLORINGS['limit-set'],
    maxIterations: 200,
    center: [0, 0.8],
    scale: 2.5,
  }),
};
