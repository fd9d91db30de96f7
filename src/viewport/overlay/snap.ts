/**
 * Snapping math for Shift-drags in the render (pure, world units). Which rule applies to which
 * handle is decided in snap-rules.ts; here are only the formulas.
 */
import type { Circle, Vec2 } from '../../../nodes/core/values.ts';
import { dist } from '../../../nodes/geometry/vec.ts';

/**
 * The smallest "nice" grid step s = m·10^k (m ∈ {1, 2, 5}) whose cell is at least `minCellPx`
 * pixels wide at `pxPerWorld` pixels per world unit, so cells are minCellPx … 2.5·minCellPx wide.
 */
export function niceGridStep(pxPerWorld: number, minCellPx: number): number {
  const minWorld = minCellPx / pxPerWorld;
  let k = Math.floor(Math.log10(minWorld));
  // log10 can be off by one ulp around exact powers of ten: walk until 10^k ≤ minWorld < 10^(k+1).
  while (10 ** k > minWorld) k--;
  while (10 ** (k + 1) <= minWorld) k++;
  for (const m of [1, 2, 5, 10]) {
    const step = m * 10 ** k;
    if (step >= minWorld * (1 - 1e-12)) return step;
  }
  return 10 ** (k + 1);
}

/** Rounds each coordinate to the nearest multiple of `step`: p ↦ step·round(p / step). */
export function snapToGrid(p: Vec2, step: number): Vec2 {
  return [Math.round(p[0] / step) * step, Math.round(p[1] / step) * step];
}

/**
 * Turns p about `pivot` to the nearest direction θ' = k·π/n (keeping |p − pivot|):
 * θ = atan2(p − pivot), θ' = round(θ n/π)·π/n, result = pivot + |p − pivot|(cos θ', sin θ').
 * A point on the pivot stays where it is.
 */
export function snapAngle(p: Vec2, pivot: Vec2, divisions: number): Vec2 {
  const dx = p[0] - pivot[0];
  const dy = p[1] - pivot[1];
  const length = Math.hypot(dx, dy);
  if (length === 0) return p;
  const unit = Math.PI / divisions;
  const theta = Math.round(Math.atan2(dy, dx) / unit) * unit;
  return [pivot[0] + length * Math.cos(theta), pivot[1] + length * Math.sin(theta)];
}

/**
 * Turns p about `pivot` so the line pivot → p meets a line of direction angle `ref` at π/n, for the
 * n in 2..maxN (mirrors meeting at π/n tile): the candidate directions are ref ± π/n and
 * ref + π ± π/n; the one nearest p's direction wins, |p − pivot| is kept. Returns the point and n.
 */
export function snapAngleToLine(p: Vec2, pivot: Vec2, ref: number, maxN: number): { at: Vec2; n: number } {
  const length = Math.hypot(p[0] - pivot[0], p[1] - pivot[1]);
  if (length === 0) return { at: p, n: 2 };
  const theta = Math.atan2(p[1] - pivot[1], p[0] - pivot[0]);
  /** |a − b| as angles, in [0, π]. */
  const gap = (a: number, b: number) => Math.abs(Math.atan2(Math.sin(a - b), Math.cos(a - b)));
  let best = { dir: ref + Math.PI / 2, n: 2 };
  for (let n = 2; n <= maxN; n++) {
    for (const dir of [
      ref + Math.PI / n,
      ref - Math.PI / n,
      ref + Math.PI + Math.PI / n,
      ref + Math.PI - Math.PI / n,
    ]) {
      if (gap(dir, theta) < gap(best.dir, theta)) best = { dir, n };
    }
  }
  return { at: [pivot[0] + length * Math.cos(best.dir), pivot[1] + length * Math.sin(best.dir)], n: best.n };
}

/**
 * Radii r at which a circle centred at c touches `other` = (c2, r2), with d = |c − c2|:
 * externally when d = r + r2 (r = d − r2, needs d > r2), internally when d = |r − r2|
 * (r = r2 − d inside it, needs d < r2; or r = d + r2 around it). Concentric circles never touch.
 */
export function tangentRadii(c: Vec2, other: Circle): number[] {
  const d = dist(c, other.c);
  if (!(d > 1e-12 * Math.max(1, other.r))) return [];
  const radii = [d + other.r];
  if (d > other.r) radii.push(d - other.r);
  if (d < other.r) radii.push(other.r - d);
  return radii;
}

export interface TangentSnap {
  readonly radius: number;
  /** Index of the circle (in `others`) it touches. */
  readonly index: number;
}

/**
 * The tangent radius (over every circle in `others`) closest to `radius`, when it is within
 * `tolerance`; null otherwise.
 */
export function snapRadiusToTangent(
  c: Vec2,
  radius: number,
  others: readonly Circle[],
  tolerance: number,
): TangentSnap | null {
  let best: TangentSnap | null = null;
  let bestGap = tolerance;
  others.forEach((other, index) => {
    for (const r of tangentRadii(c, other)) {
      const gap = Math.abs(r - radius);
      if (gap <= bestGap) {
        bestGap = gap;
        best = { radius: r, index };
      }
    }
  });
  return best;
}

/** The point at distance `radius` from c in the direction of `toward` (c + radius·û; +x when toward = c). */
export function pointAtRadius(c: Vec2, toward: Vec2, radius: number): Vec2 {
  const dx = toward[0] - c[0];
  const dy = toward[1] - c[1];
  const l = Math.hypot(dx, dy);
  return l > 0 ? [c[0] + (radius * dx) / l, c[1] + (radius * dy) / l] : [c[0] + radius, c[1]];
}

/** Rounds the distance |p − c| to a positive multiple of `step`, keeping the direction from c. */
export function snapRadiusToStep(c: Vec2, p: Vec2, step: number): Vec2 {
  const r = Math.max(step, Math.round(dist(c, p) / step) * step);
  return pointAtRadius(c, p, r);
}
