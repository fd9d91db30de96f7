/**
 * Checks the mirrors a render draws, so that a wrong picture never comes without a message
 * (docs/math.md: the IIS tile is the common part of the sides every mirror keeps):
 * - KF406 kept sides: the mirrors keep no common region (nothing is the tile), or at least three
 *   line mirrors enclose a polygon but keep an unbounded region beyond one of its edges (the
 *   "AB, AC, BC" triangle, whose middle line keeps the outside). The warning sits on each mirror
 *   to flip — the fewest flips that give a common region, a bounded one where lines can bound one
 *   — and offers the flip as a fix.
 * - KF407 angles: two line mirrors that are adjacent sides of the kept region must meet at π/n, or
 *   their images overlap (mirror-angles.ts; a triangle of lines snaps whole, mirror-triangle.ts).
 * Pure: the geometry is in nodes/geometry/kept-region.ts and triangle-snap.ts.
 */
import { type Diagnostic, type DiagnosticFix, diag } from '../core/diagnostics.ts';
import type { SceneElement } from '../core/scene.ts';
import { commonInteriorPoint, flipSide, isBounded, type KeptSide } from '../geometry/kept-region.ts';
import { angleDiagnostics, type Mirror, type MirrorGraph } from './mirror-angles.ts';
import { nodeName } from './node-names.ts';

export { ANGLE_TOLERANCE, formatPiOver, type MirrorGraph } from './mirror-angles.ts';

/** The most flips tried together when looking for the fix. */
const MAX_FLIPS = 3;
/** Flip sets tried at most, and the most mirrors a flip search runs for (see findFlips). */
const FLIP_TRIES = 64;
const FLIP_SEARCH_MIRRORS = 12;
/**
 * Scenes with more mirrors than this are not checked: the test is O(m³) and runs on every frame of
 * a drag (a few ms at 32); such scenes are built from the tiling nodes, which are right by design.
 */
export const MAX_CHECKED_MIRRORS = 32;

/** Sides kept by the scene's reflections and inversions, in scene order. */
export function keptSideOf(e: SceneElement): KeptSide | null {
  if (e.kind === 'reflection') return { kind: 'half-plane', q: e.q, n: e.n };
  if (e.kind === 'inversion') return { kind: 'disk', c: e.c, r: e.r, keepInside: false };
  if (e.kind === 'outer-inversion') return { kind: 'disk', c: e.c, r: e.r, keepInside: true };
  return null;
}

function mirrorsOf(elements: readonly SceneElement[], graph: MirrorGraph): Mirror[] {
  const perNode = new Map<string, number>();
  for (const e of elements) perNode.set(e.nodeId, (perNode.get(e.nodeId) ?? 0) + 1);
  const mirrors: Mirror[] = [];
  for (const e of elements) {
    const side = keptSideOf(e);
    if (!side) continue;
    const def = graph.analysis.nodes.get(e.nodeId)?.def;
    const flip = graph.nodes.get(e.nodeId)?.ctx?.params.flip;
    const flippable = def?.params.flip?.kind === 'boolean' && perNode.get(e.nodeId) === 1;
    mirrors.push({
      nodeId: e.nodeId,
      name: nodeName(graph.analysis.nodes, e.nodeId),
      side,
      flip: flippable && typeof flip === 'boolean' ? flip : null,
    });
  }
  return mirrors;
}

/** Index sets of `pool` of size k, in lexicographic order. */
function* subsets(pool: readonly number[], k: number, from = 0): Generator<number[]> {
  if (k === 0) {
    yield [];
    return;
  }
  for (let i = from; i <= pool.length - k; i++)
    for (const rest of subsets(pool, k - 1, i + 1)) yield [pool[i], ...rest];
}

/**
 * The fewest flips among `pool` after which the sides have a common interior (bounded, if asked).
 * Each try costs O(m³) for m mirrors, and this runs on every evaluation (every drag frame), so the
 * search stops after FLIP_TRIES tries and is skipped above FLIP_SEARCH_MIRRORS mirrors.
 */
function findFlips(sides: readonly KeptSide[], pool: readonly number[], mustBound: boolean): number[] | null {
  if (sides.length > FLIP_SEARCH_MIRRORS) return null;
  let tries = 0;
  for (let k = 1; k <= Math.min(MAX_FLIPS, pool.length); k++) {
    for (const set of subsets(pool, k)) {
      const flipped = sides.map((s, i) => (set.includes(i) ? flipSide(s) : s));
      if (mustBound && !isBounded(flipped)) continue;
      if (++tries > FLIP_TRIES) return null;
      if (commonInteriorPoint(flipped)) return set;
    }
  }
  return null;
}

function flipDiagnostics(mirrors: readonly Mirror[], set: readonly number[], why: string): Diagnostic[] {
  const all = set.map((i) => mirrors[i].name);
  const names = all.length > 1 ? `${all.slice(0, -1).join(', ')} and ${all.at(-1)}` : all[0];
  const fix: DiagnosticFix = {
    label: `Flip ${names}`,
    params: set.map((i) => ({ nodeId: mirrors[i].nodeId, params: { flip: !mirrors[i].flip } })),
  };
  return set.map((i) => ({
    ...diag(
      'keptSides',
      { nodeId: mirrors[i].nodeId },
      `${mirrors[i].name} keeps the wrong side: ${why}. Flip ${names}.`,
    ),
    fix,
  }));
}

/** KF406: the kept sides of the render's mirrors (see the file comment). */
function keptSideDiagnostics(mirrors: readonly Mirror[], renderNodeId: string): Diagnostic[] {
  const sides = mirrors.map((m) => m.side);
  const flippable = mirrors.flatMap((m, i) => (m.flip === null ? [] : [i]));
  if (!commonInteriorPoint(sides)) {
    // Lines that can bound a polygon should: try the fewest flips giving a bounded region first.
    const set = findFlips(sides, flippable, true) ?? findFlips(sides, flippable, false);
    const why =
      'as wired, the mirrors keep no common region, so nothing is the tile and the picture is wrong';
    if (set) return flipDiagnostics(mirrors, set, why);
    return [
      diag(
        'keptSides',
        { nodeId: renderNodeId },
        'the mirrors wired in keep no common region, so nothing is the tile and the picture is wrong: flip a mirror (a line keeps its left side, a circle its outside)',
      ),
    ];
  }
  const lines = flippable.filter((i) => sides[i].kind === 'half-plane');
  if (sides.filter((s) => s.kind === 'half-plane').length < 3 || lines.length === 0 || isBounded(sides))
    return [];
  const set = findFlips(sides, lines, true);
  return set
    ? flipDiagnostics(
        mirrors,
        set,
        'the line mirrors enclose a polygon but keep an unbounded region beyond one of its edges, so the picture is not a tiling',
      )
    : [];
}

/** Every KF406/KF407 warning for the render's elements (angles only once the sides are right). */
export function mirrorDiagnostics(
  elements: readonly SceneElement[],
  renderNodeId: string,
  graph: MirrorGraph,
): Diagnostic[] {
  const mirrors = mirrorsOf(elements, graph);
  if (mirrors.length === 0 || mirrors.length > MAX_CHECKED_MIRRORS) return [];
  const sides = keptSideDiagnostics(mirrors, renderNodeId);
  return sides.length > 0 ? sides : angleDiagnostics(mirrors, graph);
}
