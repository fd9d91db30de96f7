/**
 * The sides mirrors keep (pure). A line mirror keeps the closed half-plane (p − q)·n ≥ 0 (its left
 * side; `flip` keeps the right), a circle mirror keeps the outside |p − c| ≥ r. The IIS tile is the
 * common part of every kept side, so when those sides have no common interior nothing is the tile
 * and the picture is wrong — this module finds out, exactly up to a tolerance ε (below).
 *
 * Method (arrangement sampling): every connected piece of the common interior I, when I is neither
 * empty nor the whole plane, has part of some mirror's boundary curve as its edge. Cut every curve
 * at its crossings with all other curves: on each open arc between consecutive crossings no other
 * curve changes sign, so if any point of an arc borders I, its midpoint does too. Testing the
 * midpoint of every arc (and a far point on each end of a line), stepped ε onto the curve's kept
 * side, against every kept side therefore finds a point of I whenever I contains a disk of radius
 * about ε next to that midpoint — O(m²) candidates for m mirrors, each tested in O(m).
 */
import type { Circle, Line, Vec2 } from '../core/values.ts';
import { intersectCircles, intersectLineCircle, intersectLines } from './intersect.ts';
import { add, dot, len, perp, scale, sub } from './vec.ts';

/** What one mirror keeps: a closed half-plane (p − q)·n ≥ 0 (n unit), or a disk's outside/inside. */
export type KeptSide =
  | { readonly kind: 'half-plane'; readonly q: Vec2; readonly n: Vec2 }
  | { readonly kind: 'disk'; readonly c: Vec2; readonly r: number; readonly keepInside: boolean };

/** The other side of the same mirror. */
export function flipSide(s: KeptSide): KeptSide {
  return s.kind === 'half-plane'
    ? { kind: 'half-plane', q: s.q, n: [-s.n[0], -s.n[1]] }
    : { ...s, keepInside: !s.keepInside };
}

/** Signed distance of p into the kept side: > 0 inside it, 0 on the mirror, < 0 on the other side. */
export function depthInSide(s: KeptSide, p: Vec2): number {
  // No allocation: this runs O(m³) times per check (see commonInteriorPoint).
  if (s.kind === 'half-plane') return (p[0] - s.q[0]) * s.n[0] + (p[1] - s.q[1]) * s.n[1];
  const d = Math.hypot(p[0] - s.c[0], p[1] - s.c[1]) - s.r;
  return s.keepInside ? -d : d;
}

/** A length that sets the tolerances: the largest coordinate or radius, at least 1. */
function sizeOf(sides: readonly KeptSide[]): number {
  let size = 1;
  for (const s of sides) {
    const at = s.kind === 'half-plane' ? s.q : s.c;
    size = Math.max(size, Math.abs(at[0]), Math.abs(at[1]), s.kind === 'disk' ? s.r : 0);
  }
  return size;
}

const asLine = (s: KeptSide & { kind: 'half-plane' }): Line => ({
  a: s.q,
  b: add(s.q, [s.n[1], -s.n[0]]), // direction d with perp(d) = n
});
const asCircle = (s: KeptSide & { kind: 'disk' }): Circle => ({ c: s.c, r: s.r });

/** Where the boundaries of two sides cross (tangent points once or twice, none when parallel). */
function crossings(s: KeptSide, t: KeptSide): readonly Vec2[] {
  const hit =
    s.kind === 'half-plane'
      ? t.kind === 'half-plane'
        ? intersectLines(asLine(s), asLine(t))
        : intersectLineCircle(asLine(s), asCircle(t))
      : t.kind === 'half-plane'
        ? intersectLineCircle(asLine(t), asCircle(s))
        : intersectCircles(asCircle(s), asCircle(t));
  return hit.ok ? hit.points : [];
}

/**
 * Points on side i's boundary: the midpoints of the arcs its crossings cut it into, and for a line
 * a far point beyond each end. Each comes with the unit direction into the kept side there.
 */
function arcMidpoints(sides: readonly KeptSide[], i: number, far: number): { at: Vec2; into: Vec2 }[] {
  const s = sides[i];
  const params: number[] = [];
  if (s.kind === 'half-plane') {
    const d: Vec2 = [s.n[1], -s.n[0]];
    for (let j = 0; j < sides.length; j++)
      if (j !== i) for (const p of crossings(s, sides[j])) params.push(dot(sub(p, s.q), d));
    params.sort((a, b) => a - b);
    const ts =
      params.length === 0
        ? [0]
        : [params[0] - far, ...params.slice(1).map((t, k) => (t + params[k]) / 2), params.at(-1)! + far];
    return ts.map((t) => ({ at: add(s.q, scale(d, t)), into: s.n }));
  }
  for (let j = 0; j < sides.length; j++)
    if (j !== i)
      for (const p of crossings(s, sides[j])) params.push(Math.atan2(p[1] - s.c[1], p[0] - s.c[0]));
  params.sort((a, b) => a - b);
  const angles =
    params.length === 0
      ? [0, Math.PI]
      : params.map((t, k) =>
          k + 1 < params.length ? (t + params[k + 1]) / 2 : (t + params[0] + 2 * Math.PI) / 2,
        );
  return angles.map((t) => {
    const out: Vec2 = [Math.cos(t), Math.sin(t)];
    return { at: add(s.c, scale(out, s.r)), into: s.keepInside ? scale(out, -1) : out };
  });
}

/**
 * A point strictly inside every kept side (depth > 0 in each), or null when they have no common
 * interior wider than about ε = 1e-7 × (largest coordinate or radius). No sides: the origin.
 */
export function commonInteriorPoint(sides: readonly KeptSide[]): Vec2 | null {
  if (sides.length === 0) return [0, 0];
  const size = sizeOf(sides);
  const eps = 1e-7 * size;
  const inAll = (p: Vec2) => sides.every((s) => depthInSide(s, p) > 1e-3 * eps);
  for (let i = 0; i < sides.length; i++) {
    for (const { at, into } of arcMidpoints(sides, i, 10 * size)) {
      const p = add(at, scale(into, eps));
      if (inAll(p)) return p;
    }
  }
  return null;
}

/**
 * Whether the common part of the sides is bounded, given that it has an interior. A kept disk
 * inside bounds it; otherwise only the half-planes can: their intersection is unbounded exactly
 * when some direction d ≠ 0 has n·d ≥ 0 for every normal n (its recession cone). That cone's edges
 * lie along ±perp(n) of some normal, so those are the only directions to try. (Outsides of disks
 * never bound: an unbounded convex region with an interior has room far out beyond every disk.)
 */
export function isBounded(sides: readonly KeptSide[]): boolean {
  if (sides.some((s) => s.kind === 'disk' && s.keepInside)) return true;
  const normals = sides.flatMap((s) => (s.kind === 'half-plane' ? [s.n] : []));
  if (normals.length < 3) return false; // two half-planes are a strip, a wedge or a half-plane
  const tol = 1e-12;
  for (const n of normals) {
    for (const d of [perp(n), scale(perp(n), -1)]) {
      if (len(d) > 0 && normals.every((m) => dot(m, d) >= -tol)) return false;
    }
  }
  return true;
}
