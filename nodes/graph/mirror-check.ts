/**
 * Checks the mirrors a render draws, so that a wrong picture never comes without a message
 * (docs/math.md: the IIS tile is the common part of the sides every mirror keeps):
 * - KF406 kept sides: the mirrors keep no common region (nothing is the tile), or at least three
 *   line mirrors enclose a polygon but keep an unbounded region beyond one of its edges (the
 *   "AB, AC, BC" triangle, whose middle line keeps the outside). The warning sits on each mirror
 *   to flip — the fewest flips that give a common region, a bounded one where lines can bound one
 *   — and offers the flip as a fix.
 * - KF407 angles: two line mirrors that are adjacent sides of the kept region must meet at π/n, or
 *   their images overlap. The warning shows the angle as π/x and offers to snap it to the nearest
 *   π/n by turning one line about its other point.
 * Pure: the geometry is in nodes/geometry/kept-region.ts.
 */
import type { EvalContext } from '../core/define-node.ts';
import { type Diagnostic, type DiagnosticFix, diag } from '../core/diagnostics.ts';
import type { SceneElement } from '../core/scene.ts';
import type { Line, Vec2 } from '../core/values.ts';
import {
  commonInteriorPoint,
  depthInSide,
  flipSide,
  isBounded,
  type KeptSide,
} from '../geometry/kept-region.ts';
import { add, dist, dot, rotate, scale, sub } from '../geometry/vec.ts';
import type { Analysis } from './analyze.ts';

/** Largest angle error (radians) still accepted as π/n: 1e-4 rad ≈ 0.006°, invisible in a picture. */
export const ANGLE_TOLERANCE = 1e-4;
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

interface Mirror {
  readonly nodeId: string;
  readonly name: string;
  readonly side: KeptSide;
  /** The node's `flip` toggle when it has one (and makes only this mirror), else null. */
  readonly flip: boolean | null;
}

/** What the check needs to know about the graph around the scene's mirrors. */
export interface MirrorGraph {
  readonly analysis: Analysis;
  /** Each node's outputs (evaluate.ts's NodeEvaluation, structurally: no import back to it). */
  readonly nodes: ReadonlyMap<
    string,
    { readonly outputs?: Readonly<Record<string, unknown>>; readonly ctx?: EvalContext }
  >;
}

/** Sides kept by the scene's reflections and inversions, in scene order. */
export function keptSideOf(e: SceneElement): KeptSide | null {
  if (e.kind === 'reflection') return { kind: 'half-plane', q: e.q, n: e.n };
  if (e.kind === 'inversion') return { kind: 'disk', c: e.c, r: e.r, keepInside: false };
  if (e.kind === 'outer-inversion') return { kind: 'disk', c: e.c, r: e.r, keepInside: true };
  return null;
}

/** “label”, else the node type's name and id: how messages name a node. */
export function nodeName(graph: MirrorGraph, nodeId: string): string {
  const entry = graph.analysis.nodes.get(nodeId);
  if (entry?.node.label) return `“${entry.node.label}”`;
  return `${entry?.def?.label ?? 'node'} “${nodeId}”`;
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
      name: nodeName(graph, e.nodeId),
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

/** Where the line mirror `m` gets its line, and how the fix moves one of its points. */
function lineSource(graph: MirrorGraph, nodeId: string): { line: Line; owner: string | null } | null {
  const edge = graph.analysis.incoming.get(nodeId)?.get('line')?.[0];
  if (!edge) {
    const line = graph.nodes.get(nodeId)?.ctx?.inputs.line as Line | undefined;
    return line ? { line, owner: null } : null;
  }
  const from = graph.analysis.nodes.get(edge.from.node);
  const line = graph.nodes.get(edge.from.node)?.outputs?.[edge.from.port] as Line | undefined;
  // Only a Line node has handles "a" and "b"; a constructed line (bisector…) has no free point.
  return from?.node.type === 'line' && line ? { line, owner: edge.from.node } : null;
}

/** Kept angle of a wedge with side normals n1, n2: π − ∠(n1, n2). */
const wedgeAngle = (n1: Vec2, n2: Vec2) => Math.PI - Math.acos(Math.max(-1, Math.min(1, dot(n1, n2))));

/** π/x with x to two decimals, and degrees: "π/2.37 (76.0°)". */
export const formatPiOver = (angle: number) =>
  `π/${(Math.PI / angle).toFixed(2).replace(/\.?0+$/, '')} (${((angle * 180) / Math.PI).toFixed(1)}°)`;

/**
 * The fix that turns mirror `nodeId`'s line (normal `normal`) about its point nearer the corner so its kept angle with
 * normal `other` becomes π/n: the farther point P moves to Q + R(δ)(P − Q), which turns the line's
 * direction (and normal) by δ whichever end P is.
 */
function snapFix(
  graph: MirrorGraph,
  nodeId: string,
  normal: Vec2,
  other: Vec2,
  corner: Vec2,
  n: number,
): DiagnosticFix | undefined {
  const source = lineSource(graph, nodeId);
  if (!source) return undefined;
  const { a, b } = source.line;
  const moveB = dist(b, corner) >= dist(a, corner);
  const [pivot, free] = moveB ? [a, b] : [b, a];
  const target = Math.PI / n;
  const now = wedgeAngle(other, normal);
  const deltas = [target - now, now - target];
  const delta = deltas.reduce((best, d) =>
    Math.abs(wedgeAngle(other, rotate(normal, d)) - target) <
    Math.abs(wedgeAngle(other, rotate(normal, best)) - target)
      ? d
      : best,
  );
  const to = add(pivot, rotate(sub(free, pivot), delta));
  const handle = moveB ? 'b' : 'a';
  const label = `Snap to π/${n}`;
  if (source.owner) return { label, moves: [{ nodeId: source.owner, handle, to }] };
  return { label, params: [{ nodeId, params: { line: { ...source.line, [handle]: to } } }] };
}

/** KF407: adjacent line mirrors of the kept region that do not meet at π/n. */
function angleDiagnostics(mirrors: readonly Mirror[], graph: MirrorGraph): Diagnostic[] {
  const sides = mirrors.map((m) => m.side);
  const size = Math.max(
    1,
    ...sides.map((s) => (s.kind === 'half-plane' ? Math.hypot(...s.q) : Math.hypot(...s.c) + s.r)),
  );
  const eps = 1e-6 * size;
  const inRegion = (p: Vec2) => sides.every((s) => depthInSide(s, p) > 0);
  const out: Diagnostic[] = [];
  for (let j = 0; j < mirrors.length; j++) {
    const sj = sides[j];
    if (sj.kind !== 'half-plane') continue;
    for (let i = 0; i < j; i++) {
      const si = sides[i];
      if (si.kind !== 'half-plane') continue;
      const den = si.n[0] * sj.n[1] - si.n[1] * sj.n[0];
      if (Math.abs(den) < 1e-9) continue; // parallel: they never meet
      // Corner V: n_i·V = n_i·q_i and n_j·V = n_j·q_j (Cramer's rule).
      const ci = dot(si.n, si.q);
      const cj = dot(sj.n, sj.q);
      const corner: Vec2 = [(ci * sj.n[1] - cj * si.n[1]) / den, (si.n[0] * cj - sj.n[0] * ci) / den];
      // Along each line from V into the other's kept side, just inside: both must border the region.
      const along = (s: typeof si, o: typeof si): Vec2 => {
        const d: Vec2 = [s.n[1], -s.n[0]];
        return dot(d, o.n) >= 0 ? d : scale(d, -1);
      };
      const ti = along(si, sj);
      const tj = along(sj, si);
      const edgeI = add(corner, scale(add(ti, scale(si.n, 0.01)), eps));
      const edgeJ = add(corner, scale(add(tj, scale(sj.n, 0.01)), eps));
      if (!inRegion(edgeI) || !inRegion(edgeJ)) continue;
      const angle = wedgeAngle(si.n, sj.n);
      const n = Math.max(2, Math.round(Math.PI / angle));
      if (Math.abs(angle - Math.PI / n) <= ANGLE_TOLERANCE) continue;
      // The later mirror turns, unless only the earlier one has a free point.
      const [moving, fixed] =
        lineSource(graph, mirrors[j].nodeId) || !lineSource(graph, mirrors[i].nodeId) ? [j, i] : [i, j];
      const [sm, sf] = moving === j ? [sj, si] : [si, sj];
      const fix = snapFix(graph, mirrors[moving].nodeId, sm.n, sf.n, corner, n);
      const text = `${mirrors[moving].name} meets ${mirrors[fixed].name} at ${formatPiOver(angle)}, not π/n: their images overlap and the picture is not a tiling (nearest: π/${n})`;
      out.push({ ...diag('mirrorAngle', { nodeId: mirrors[moving].nodeId }, text), ...(fix ? { fix } : {}) });
    }
  }
  return out;
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
