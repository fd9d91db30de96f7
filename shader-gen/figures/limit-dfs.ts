/**
 * The limit set by depth-first search of the reduced words (the idea of Indra's Pearls; docs/math.md
 * "Cayley graph and depth-first limit set"). For a Schottky-type group each generator T_k maps the
 * outside of its inverse's disk D_{k⁻¹} into its own disk D_k, so the disks of a reduced word
 * x₁…xₙ, D(x₁…xₙ) = x₁…xₙ₋₁(D_{xₙ}), are nested. A branch stops when its disk is smaller than a
 * pixel: the disk's centre is then within a pixel of the limit set, and is written out. Leaves come
 * out in the limit set's cyclic order; consecutive ones closer than `joinPx` are joined into curves.
 */
import type { Scene } from '../../nodes/core/scene.ts';
import type { Circle, Vec2 } from '../../nodes/core/values.ts';
import { type AntiMobius, compose, imageCircle } from '../../nodes/geometry/anti-mobius.ts';
import { sceneGenerators, schottkyDisks } from '../../nodes/geometry/group-generators.ts';

export interface DfsOptions {
  /** World units per output pixel. */
  readonly pixelWorld: number;
  readonly width: number;
  readonly height: number;
  /** A branch stops below this disk radius, in pixels (default 0.5). */
  readonly leafPx?: number;
  /** Consecutive leaves closer than this many pixels are joined (default 1.5). */
  readonly joinPx?: number;
  /** Word cap (default MAX_DFS_WORDS). */
  readonly maxWords?: number;
}

/** The most words one search visits (a few seconds of CPU); the part found is still drawn. */
export const MAX_DFS_WORDS = 2_000_000;
/** The longest word: tangent disks (parabolic fixed points) shrink only like 1/n². */
export const MAX_DFS_DEPTH = 1000;

export type LimitSetDfs =
  | {
      readonly ok: true;
      /** Polylines in the order found; a one-point polyline is an isolated point. */
      readonly curves: readonly (readonly Vec2[])[];
      readonly leaves: number;
      readonly words: number;
      /** Set when the word cap or the depth cap stopped a branch early. */
      readonly capped?: string;
    }
  | { readonly ok: false; readonly message: string; readonly nodeId?: string };

interface Branch {
  readonly map: AntiMobius;
  readonly disk: Circle;
  readonly last: number;
  readonly depth: number;
}

/** Whether the disk reaches into the view rectangle widened by `margin` (world units). */
function meetsView(k: Circle, view: Scene['view'], hw: number, hh: number, margin: number): boolean {
  const dx = Math.max(Math.abs(k.c[0] - view.center[0]) - hw - margin, 0);
  const dy = Math.max(Math.abs(k.c[1] - view.center[1]) - hh - margin, 0);
  return dx * dx + dy * dy <= k.r * k.r;
}

export function limitSetDfs(scene: Pick<Scene, 'elements' | 'view'>, options: DfsOptions): LimitSetDfs {
  const found = sceneGenerators(scene);
  if (!found.ok) return found;
  const gens = found.generators;
  const schottky = schottkyDisks(gens);
  if (!schottky.ok) return schottky;
  const { disks } = schottky;
  const { pixelWorld, width, height } = options;
  const leafR = (options.leafPx ?? 0.5) * pixelWorld;
  const join = (options.joinPx ?? 1.5) * pixelWorld;
  const cap = options.maxWords ?? MAX_DFS_WORDS;
  const hw = (width * pixelWorld) / 2;
  const hh = (height * pixelWorld) / 2;
  const curves: Vec2[][] = [];
  let current: Vec2[] | null = null;
  let leaves = 0;
  let words = 0;
  let capped: string | undefined;
  const emit = (p: Vec2) => {
    leaves++;
    const prev = current?.[current.length - 1];
    if (current && prev && Math.hypot(p[0] - prev[0], p[1] - prev[1]) <= join) current.push(p);
    else {
      current = [p];
      curves.push(current);
    }
  };
  // Children pushed in reverse so that they pop in cyclic order, starting after the inverse of the
  // last letter: leaves then follow the limit set round.
  const stack: Branch[] = [];
  for (let k = gens.length - 1; k >= 0; k--)
    stack.push({ map: gens[k].map, disk: disks[k], last: k, depth: 1 });
  const n = gens.length;
  while (stack.length > 0) {
    const b = stack.pop() as Branch;
    if (++words > cap) {
      capped = `the depth-first search stopped at ${cap} words: zoom in, or it draws only part of the limit set`;
      break;
    }
    if (!meetsView(b.disk, scene.view, hw, hh, pixelWorld)) continue;
    if (b.disk.r < leafR) {
      emit(b.disk.c);
      continue;
    }
    if (b.depth >= MAX_DFS_DEPTH) {
      capped ??= `some words reached ${MAX_DFS_DEPTH} letters before their disks shrank below a pixel (a parabolic point): their disks' centres are drawn`;
      emit(b.disk.c);
      continue;
    }
    const inv = gens[b.last].inverse;
    for (let s = n - 1; s >= 1; s--) {
      const k = (inv + s) % n;
      const disk = imageCircle(b.map, disks[k]);
      if (!disk || !(disk.r < b.disk.r * (1 + 1e-9))) continue;
      stack.push({ map: compose(b.map, gens[k].map), disk, last: k, depth: b.depth + 1 });
    }
  }
  return { ok: true, curves, leaves, words, ...(capped ? { capped } : {}) };
}
