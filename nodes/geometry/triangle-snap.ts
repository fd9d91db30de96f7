/**
 * Snapping a triangle of three mirror LINES to a tiling triangle in one step
 * (docs/math.md "Snapping a mirror triangle"). Snapping one corner at a time never settles: the three angles of
 * a straight-sided triangle always sum to π, so making one corner π/n pushes another off. Here the
 * whole configuration is solved at once:
 * 1. the target: the assignment of a Euclidean triple (3, 3, 3), (2, 4, 4) or (2, 3, 6) — the only
 *    (p, q, r) with 1/p + 1/q + 1/r = 1, and three straight lines can make no other — to the three
 *    corners that changes the fewest angles already at π/n, then is nearest (sum of |Δangle|);
 * 2. the move: one side's line and both its corners stay, the opposite corner moves to where the
 *    target angles put it. Each defining point follows its line: a point on two moving lines goes
 *    to their new crossing, a point on one keeps its distance from the corner the line turns
 *    about. Of the three sides, the one that moves the fewest points wins, then the one that keeps
 *    the points listed first (a teacher's base A, B, drawn before the apex C), then the least
 *    total displacement.
 * Pure; the graph side (which nodes own the points) is nodes/graph/mirror-triangle.ts.
 */
import type { Vec2 } from '../core/values.ts';
import { add, cross, dist, dot, normalize, rotate, scale, sub } from './vec.ts';

/** The three triples a triangle of straight mirrors can have (sorted). */
export const EUCLIDEAN_TRIPLES: readonly (readonly [number, number, number])[] = [
  [3, 3, 3],
  [2, 4, 4],
  [2, 3, 6],
];

/** One mirror line, through two of the configuration's points (by id). */
export interface SnapLine {
  readonly points: readonly [string, string];
}

export interface TriangleSnapInput {
  /** Line k is the side opposite corner k; corner k is where the other two lines cross. */
  readonly lines: readonly [SnapLine, SnapLine, SnapLine];
  /** Every point the lines are defined by, in the order to keep them in (earlier = kept first). */
  readonly points: readonly { readonly id: string; readonly at: Vec2; readonly free: boolean }[];
  /** Largest error (radians) at which an angle counts as already π/n. */
  readonly tolerance: number;
}

export interface TriangleSnap {
  /** n at each corner (angle π/n), in corner order. */
  readonly orders: readonly [number, number, number];
  /** Corners whose angle was already π/n but had to change (no triple keeps them all). */
  readonly changedExact: readonly number[];
  /** The corners' angles before the snap. */
  readonly angles: readonly [number, number, number];
  /** The points that move, in input order, and where to. */
  readonly moves: readonly { readonly id: string; readonly to: Vec2 }[];
}

type Triple = [number, number, number];

/** Where lines (p1, p2) and (q1, q2) cross, or null when (nearly) parallel. */
function crossing(p1: Vec2, p2: Vec2, q1: Vec2, q2: Vec2): Vec2 | null {
  const d1 = sub(p2, p1);
  const d2 = sub(q2, q1);
  const den = cross(d1, d2);
  if (Math.abs(den) <= 1e-12 * Math.hypot(...d1) * Math.hypot(...d2)) return null;
  return add(p1, scale(d1, cross(sub(q1, p1), d2) / den));
}

/** Interior angle at v of the triangle (v, u, w). */
function angleAt(v: Vec2, u: Vec2, w: Vec2): number {
  const a = normalize(sub(u, v));
  const b = normalize(sub(w, v));
  return Math.atan2(Math.abs(cross(a, b)), dot(a, b));
}

/** The three corners of the lines' triangle (corner k opposite line k), or null if degenerate. */
export function triangleCorners(lines: readonly (readonly [Vec2, Vec2])[]): [Vec2, Vec2, Vec2] | null {
  const corner = (k: number) => {
    const [i, j] = [(k + 1) % 3, (k + 2) % 3];
    return crossing(lines[i][0], lines[i][1], lines[j][0], lines[j][1]);
  };
  const c = [corner(0), corner(1), corner(2)];
  if (c.some((p) => p === null)) return null;
  const [a, b, d] = c as Vec2[];
  return Math.abs(cross(sub(b, a), sub(d, a))) > 1e-12 * (dist(a, b) * dist(a, d) || 1) ? [a, b, d] : null;
}

export function triangleAngles(corners: readonly Vec2[]): [number, number, number] {
  const at = (k: number) => angleAt(corners[k], corners[(k + 1) % 3], corners[(k + 2) % 3]);
  return [at(0), at(1), at(2)];
}

/** The corners whose angle is π/n (n ≥ 2) within `tolerance`. */
export function exactCorners(angles: readonly number[], tolerance: number): boolean[] {
  return angles.map((a) => {
    const n = Math.max(2, Math.round(Math.PI / a));
    return Math.abs(a - Math.PI / n) <= tolerance;
  });
}

/** Every distinct assignment of the Euclidean triples to three corners. */
function assignments(): Triple[] {
  const out = new Map<string, Triple>();
  for (const [p, q, r] of EUCLIDEAN_TRIPLES)
    for (const t of [
      [p, q, r],
      [p, r, q],
      [q, p, r],
      [q, r, p],
      [r, p, q],
      [r, q, p],
    ] as Triple[])
      out.set(t.join(), t);
  return [...out.values()];
}

/**
 * Step 1: the corners' orders — fewest already-exact corners changed, then nearest. An exact
 * corner "changes" when its order differs from the π/n it is at.
 */
export function nearestOrders(
  angles: readonly number[],
  tolerance: number,
): { orders: Triple; changedExact: number[] } {
  const exact = exactCorners(angles, tolerance);
  const nOf = (a: number) => Math.max(2, Math.round(Math.PI / a));
  let best: { orders: Triple; changedExact: number[]; cost: number } | null = null;
  for (const orders of assignments()) {
    const changedExact = [0, 1, 2].filter((k) => exact[k] && orders[k] !== nOf(angles[k]));
    const cost = orders.reduce((s, n, k) => s + Math.abs(angles[k] - Math.PI / n), 0);
    if (
      !best ||
      changedExact.length < best.changedExact.length ||
      (changedExact.length === best.changedExact.length && cost < best.cost - 1e-12)
    )
      best = { orders, changedExact, cost };
  }
  return { orders: best!.orders, changedExact: best!.changedExact };
}

/**
 * Step 2 for one kept side s: corners X = s+1 and Y = s+2 stay, corner Z = s moves so the angles
 * at X and Y are the targets (then Z's is π − both, the third of the triple). Z' lies on Z's side
 * of line s: the ray from X turned from XY toward Z by the angle at X, at the distance the law of
 * sines gives.
 */
function movedApex(corners: readonly Vec2[], s: number, orders: Triple): Vec2 {
  const [x, y, z] = [corners[(s + 1) % 3], corners[(s + 2) % 3], corners[s]];
  const [ax, ay] = [Math.PI / orders[(s + 1) % 3], Math.PI / orders[(s + 2) % 3]];
  const side = Math.sign(cross(sub(y, x), sub(z, x)));
  const dir = rotate(normalize(sub(y, x)), side * ax);
  return add(x, scale(dir, (dist(x, y) * Math.sin(ay)) / Math.sin(ax + ay)));
}

/** Where every point goes when side s is kept (undefined: it stays), or null if a fixed one must move. */
function movesKeeping(
  input: TriangleSnapInput,
  corners: readonly Vec2[],
  s: number,
  apex: Vec2,
): { id: string; to: Vec2 }[] | null {
  const moves: { id: string; to: Vec2 }[] = [];
  for (const p of input.points) {
    // The moving lines this point defines: k ≠ s. Line k turns about corner (k ≠ s, so) the kept
    // corner on it, which is the one of X, Y that is not corner k.
    const on = [0, 1, 2].filter((k) => k !== s && input.lines[k].points.includes(p.id));
    if (on.length === 0 || input.lines[s].points.includes(p.id)) continue; // on a kept line
    let to: Vec2;
    if (on.length === 2) to = apex;
    else {
      const k = on[0];
      const pivot = corners[3 - s - k];
      const u = normalize(sub(corners[s], pivot));
      to = add(pivot, scale(normalize(sub(apex, pivot)), dot(sub(p.at, pivot), u)));
    }
    if (dist(to, p.at) <= 1e-12 * Math.max(1, Math.hypot(...p.at))) continue;
    if (!p.free) return null;
    moves.push({ id: p.id, to });
  }
  return moves;
}

/**
 * The one-step snap of the whole triangle, or null when the lines make no triangle, a line is not
 * given by two distinct points, or every way to snap would move a point that is not free.
 */
export function snapTriangle(input: TriangleSnapInput): TriangleSnap | null {
  const pos = new Map(input.points.map((p) => [p.id, p.at]));
  const ends = input.lines.map((l) => l.points.map((id) => pos.get(id)));
  if (ends.some(([a, b]) => !a || !b || dist(a, b) === 0)) return null;
  const corners = triangleCorners(ends as [Vec2, Vec2][]);
  if (!corners) return null;
  const angles = triangleAngles(corners);
  const { orders, changedExact } = nearestOrders(angles, input.tolerance);
  const rank = new Map(input.points.map((p, i) => [p.id, i]));
  // Fewest moved points; then keep earlier points (compare the latest-kept ranks); then nearest.
  const score = (moves: readonly { id: string; to: Vec2 }[]) => [
    moves.length,
    -Math.min(...moves.map((m) => rank.get(m.id)!), input.points.length),
    moves.reduce((sum, m) => sum + dist(m.to, pos.get(m.id)!), 0),
  ];
  const before = (a: readonly number[], b: readonly number[]) => {
    const i = a.findIndex((v, j) => v !== b[j]);
    return i >= 0 && a[i] < b[i];
  };
  let best: { moves: { id: string; to: Vec2 }[]; score: number[] } | null = null;
  for (let s = 0; s < 3; s++) {
    const moves = movesKeeping(input, corners, s, movedApex(corners, s, orders));
    if (moves && (!best || before(score(moves), best.score))) best = { moves, score: score(moves) };
  }
  if (!best) return null;
  return { orders, changedExact, angles, moves: best.moves };
}
