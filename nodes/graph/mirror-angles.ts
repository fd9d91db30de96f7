/**
 * KF407 angles (see mirror-check.ts): two line mirrors that are adjacent sides of the kept region
 * must meet at π/n, or their images overlap. The warning shows the angle as π/x. Its fix:
 * - when the kept region is a triangle of three line mirrors, ONE snap of the whole triangle to the
 *   nearest tiling triple (mirror-triangle.ts), the same fix on every corner's warning — snapping
 *   corners one at a time never settles, as the three angles always sum to π;
 * - otherwise (a wedge of two lines, a rectangle…) the corner snaps alone to the nearest π/n by
 *   turning one line about its point nearer the corner.
 * Pure.
 */
import { type Diagnostic, type DiagnosticFix, diag } from '../core/diagnostics.ts';
import type { Vec2 } from '../core/values.ts';
import { depthInSide, type KeptSide } from '../geometry/kept-region.ts';
import { add, dist, dot, rotate, scale, sub } from '../geometry/vec.ts';
import { formatTriple, lineSource, type MirrorGraph, triangleFix } from './mirror-triangle.ts';

export type { MirrorGraph } from './mirror-triangle.ts';

/** Largest angle error (radians) still accepted as π/n: 1e-4 rad ≈ 0.006°, invisible in a picture. */
export const ANGLE_TOLERANCE = 1e-4;

/** A mirror of the render, as the check sees it (mirror-check.ts builds them). */
export interface Mirror {
  readonly nodeId: string;
  readonly name: string;
  readonly side: KeptSide;
  /** The node's `flip` toggle when it has one (and makes only this mirror), else null. */
  readonly flip: boolean | null;
}

/** What the check needs to know about the graph around the scene's mirrors. */
/** Kept angle of a wedge with side normals n1, n2: π − ∠(n1, n2). */
const wedgeAngle = (n1: Vec2, n2: Vec2) => Math.PI - Math.acos(Math.max(-1, Math.min(1, dot(n1, n2))));

/** π/x with x to two decimals, and degrees: "π/2.37 (76.0°)". */
export const formatPiOver = (angle: number) =>
  `π/${(Math.PI / angle).toFixed(2).replace(/\.?0+$/, '')} (${((angle * 180) / Math.PI).toFixed(1)}°)`;

/**
 * The one-corner fix: mirror `nodeId`'s line (normal `normal`) turns about its point nearer the
 * corner so its kept angle with normal `other` becomes π/n: the farther point P moves to
 * Q + R(δ)(P − Q), which turns the line's direction (and normal) by δ whichever end P is.
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

/** A corner of the kept region where line mirrors i < j meet. */
interface Corner {
  readonly i: number;
  readonly j: number;
  readonly at: Vec2;
  readonly angle: number;
  /** The nearest n (angle ≈ π/n). */
  readonly n: number;
}

/** Every corner of the kept region where two line mirrors meet (both border the region there). */
function regionCorners(sides: readonly KeptSide[]): Corner[] {
  const size = Math.max(
    1,
    ...sides.map((s) => (s.kind === 'half-plane' ? Math.hypot(...s.q) : Math.hypot(...s.c) + s.r)),
  );
  const eps = 1e-6 * size;
  const inRegion = (p: Vec2) => sides.every((s) => depthInSide(s, p) > 0);
  const corners: Corner[] = [];
  for (let j = 0; j < sides.length; j++) {
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
      const at: Vec2 = [(ci * sj.n[1] - cj * si.n[1]) / den, (si.n[0] * cj - sj.n[0] * ci) / den];
      // Along each line from V into the other's kept side, just inside: both must border the region.
      const along = (s: typeof si, o: typeof si): Vec2 => {
        const d: Vec2 = [s.n[1], -s.n[0]];
        return dot(d, o.n) >= 0 ? d : scale(d, -1);
      };
      const edgeI = add(at, scale(add(along(si, sj), scale(si.n, 0.01)), eps));
      const edgeJ = add(at, scale(add(along(sj, si), scale(sj.n, 0.01)), eps));
      if (!inRegion(edgeI) || !inRegion(edgeJ)) continue;
      const angle = wedgeAngle(si.n, sj.n);
      corners.push({ i, j, at, angle, n: Math.max(2, Math.round(Math.PI / angle)) });
    }
  }
  return corners;
}

/** The three mirrors when the corners are exactly those of a triangle of three line mirrors. */
function triangleOf(corners: readonly Corner[]): [number, number, number] | null {
  const used = [...new Set(corners.flatMap((c) => [c.i, c.j]))];
  return corners.length === 3 && used.length === 3 ? (used as [number, number, number]) : null;
}

/** KF407: adjacent line mirrors of the kept region that do not meet at π/n. */
export function angleDiagnostics(mirrors: readonly Mirror[], graph: MirrorGraph): Diagnostic[] {
  const corners = regionCorners(mirrors.map((m) => m.side));
  const off = corners.filter((c) => Math.abs(c.angle - Math.PI / c.n) > ANGLE_TOLERANCE);
  if (off.length === 0) return [];
  const tri = triangleOf(corners);
  const whole = tri
    ? triangleFix(graph, tri.map((k) => mirrors[k].nodeId) as [string, string, string], ANGLE_TOLERANCE)
    : null;
  return off.map((c) => {
    // The later mirror turns, unless only the earlier one has a free point.
    const [moving, fixed] =
      lineSource(graph, mirrors[c.j].nodeId) || !lineSource(graph, mirrors[c.i].nodeId)
        ? [c.j, c.i]
        : [c.i, c.j];
    const [sm, sf] = [mirrors[moving].side, mirrors[fixed].side];
    let fix: DiagnosticFix | undefined;
    let nearest = `nearest: π/${c.n}`;
    if (whole) {
      fix = whole.fix;
      // The triple's order at this corner: the corner opposite the third mirror of the triangle.
      const k = tri!.findIndex((m) => m !== c.i && m !== c.j);
      const n = whole.snap.orders[k];
      nearest = `the nearest tiling triangle is ${formatTriple(whole.snap.orders)}, π/${n} here`;
      if (whole.snap.changedExact.length > 0)
        nearest +=
          '; the corners already at π/n fit no tiling triangle (three straight mirrors need (3, 3, 3), (2, 4, 4) or (2, 3, 6)), so the snap changes one of them too';
    } else if (sm.kind === 'half-plane' && sf.kind === 'half-plane')
      fix = snapFix(graph, mirrors[moving].nodeId, sm.n, sf.n, c.at, c.n);
    const text = `${mirrors[moving].name} meets ${mirrors[fixed].name} at ${formatPiOver(c.angle)}, not π/n: their images overlap and the picture is not a tiling (${nearest})`;
    return { ...diag('mirrorAngle', { nodeId: mirrors[moving].nodeId }, text), ...(fix ? { fix } : {}) };
  });
}
