/**
 * The cusps of the Maskit slice (docs/math.md "The Maskit slice boundary"): for each fraction p/q,
 * the parameter μ where the Farey word W_{p/q} of Maskit's group a(z) = μ + 1/z, b(z) = z + 2 is
 * parabolic, tr W_{p/q}(μ) = 2, on the p/q pleating ray (Indra's Pearls, ch. 9, "Maskit slice").
 * Ordered by p/q in [0, 1] they trace the slice's boundary from 2i (0/1) to −2 + 2i (1/1).
 */
import { type Complex, cabs, cadd, cdiv, cmul, csub } from './complex.ts';

/** A value of a trace polynomial and its derivative in μ (a dual number over ℂ). */
interface TraceDual {
  readonly t: Complex;
  readonly dt: Complex;
}

/** tr(XY) = tr X · tr Y − tr(XY⁻¹), carried with the derivative (product rule). */
const traceOfProduct = (x: TraceDual, y: TraceDual, xyInv: TraceDual): TraceDual => ({
  t: csub(cmul(x.t, y.t), xyInv.t),
  dt: csub(cadd(cmul(x.dt, y.t), cmul(x.t, y.dt)), xyInv.dt),
});

/**
 * tr W_{p/q}(μ) and d/dμ, for 0 ≤ p/q (q ≥ 1, gcd 1), by descending the Stern–Brocot tree from
 * W_{0/1} = a (tr −iμ) and W_{1/0} = b (tr 2): the word of the mediant of neighbours L < R is
 * W_L·W_R, so tr W_M = tr W_L·tr W_R − tr(W_L W_R⁻¹), where W_L W_R⁻¹ is (conjugate to) the word
 * of the neighbour the pair was split from — b⁻¹·… at the start, tr(ab⁻¹) = −i(μ − 2).
 */
export function fareyTrace(p: number, q: number, mu: Complex): TraceDual {
  let left: TraceDual = { t: [mu[1], -mu[0]], dt: [0, -1] };
  let right: TraceDual = { t: [2, 0], dt: [0, 0] };
  let split: TraceDual = { t: [mu[1], 2 - mu[0]], dt: [0, -1] };
  let [pl, ql, pr, qr] = [0, 1, 1, 0];
  if (p === 0 && q === 1) return left;
  for (;;) {
    const [pm, qm] = [pl + pr, ql + qr];
    const mid = traceOfProduct(left, right, split);
    if (pm === p && qm === q) return mid;
    if (qm > q) throw new Error(`${p}/${q} is not a reduced fraction ≥ 0`);
    if (p * qm < pm * q) {
      split = right;
      right = mid;
      [pr, qr] = [pm, qm];
    } else {
      split = left;
      left = mid;
      [pl, ql] = [pm, qm];
    }
  }
}

/** Newton steps on tr W_{p/q}(μ) = target from μ; null when it does not settle. */
function solveTrace(p: number, q: number, target: number, mu: Complex, steps: number): Complex | null {
  let z = mu;
  for (let k = 0; k < steps; k++) {
    const { t, dt } = fareyTrace(p, q, z);
    const dz = cdiv(csub(t, [target, 0]), dt);
    if (!Number.isFinite(dz[0]) || !Number.isFinite(dz[1])) return null;
    z = csub(z, dz);
    if (cabs(dz) <= 1e-14 * Math.max(1, cabs(z))) break;
  }
  return z;
}

/** Heights of the start of the pleating ray and the number of steps down it. */
const RAY_TOP = 4;
const RAY_STEPS = 24;

/**
 * The p/q cusp by following the pleating ray, where tr W_{p/q} is real and > 2, down from above
 * (Indra's Pearls, ch. 9): for large Im μ, tr W_{p/q} ≈ (−i)^q (μ + 2p/q)^q, real and positive on
 * Re μ = −2p/q; from there Newton follows tr W = τ^q as τ goes down to 2^{1/q}, each solve
 * starting from the last, and ends at tr W = 2 — the root on this ray, not one of the q − 1 others.
 */
export function maskitCusp(p: number, q: number): Complex {
  let mu: Complex = [(-2 * p) / q, RAY_TOP];
  const top = Math.max(2, fareyTrace(p, q, mu).t[0]) ** (1 / q);
  const bottom = 2 ** (1 / q);
  for (let k = 0; k <= RAY_STEPS; k++) {
    const tau = top + ((bottom - top) * k) / RAY_STEPS;
    const next = solveTrace(p, q, k === RAY_STEPS ? 2 : tau ** q, mu, k === RAY_STEPS ? 40 : 4);
    if (!next) throw new Error(`Newton lost the ${p}/${q} pleating ray`);
    mu = next;
  }
  return mu;
}

/** One vertex of the boundary polyline: the cusp μ of p/q. */
export interface MaskitCusp {
  readonly p: number;
  readonly q: number;
  readonly mu: Complex;
}

/** The largest denominator the slice node offers (181 cusps from 0/1 to 1/1). */
export const MASKIT_MAX_DENOMINATOR = 24;

/** The Farey sequence of order n: every reduced p/q in [0, 1] with q ≤ n, increasing. */
export function fareySequence(n: number): [number, number][] {
  const out: [number, number][] = [[0, 1]];
  // Next term after a/b, c/d: k = ⌊(n + b)/d⌋, then (kc − a)/(kd − b).
  let [a, b, c, d] = [0, 1, 1, n];
  while (c <= n) {
    out.push([c, d]);
    const k = Math.floor((n + b) / d);
    [a, b, c, d] = [c, d, k * c - a, k * d - b];
    if (a === 1 && b === 1) break;
  }
  return out;
}

let cached: readonly MaskitCusp[] | null = null;

/**
 * The cusps of every p/q in [0, 1] with q ≤ MASKIT_MAX_DENOMINATOR, in Farey order: the boundary
 * polyline from 2i to −2 + 2i (one period; the slice is invariant under μ ↦ μ + 2). Computed once.
 */
export function maskitCusps(): readonly MaskitCusp[] {
  cached ??= fareySequence(MASKIT_MAX_DENOMINATOR).map(([p, q]) => ({ p, q, mu: maskitCusp(p, q) }));
  return cached;
}

/** The polyline through the cusps with q ≤ maxQ, as flat arrays, per maxQ (the CPU raster asks per pixel). */
const polylines = new Map<number, { readonly xs: Float64Array; readonly ys: Float64Array }>();
function polyline(maxQ: number) {
  let line = polylines.get(maxQ);
  if (!line) {
    const kept = maskitCusps().filter((c) => c.q <= maxQ);
    line = { xs: Float64Array.from(kept, (c) => c.mu[0]), ys: Float64Array.from(kept, (c) => c.mu[1]) };
    polylines.set(maxQ, line);
  }
  return line;
}

/** x folded into one period, [−2, 0): x − 2⌊x/2 + 1⌋. */
const foldPeriod = (x: number) => x - 2 * Math.floor(x * 0.5 + 1);

/**
 * Whether μ = x + iy lies strictly below the boundary polyline through the cusps with q ≤ maxQ
 * (docs/math.md "The Maskit slice boundary"): fold x into [−2, 0), take |y| (μ̄ gives the
 * complex-conjugate group), and count the polyline's crossings of the upward ray from there — odd
 * means below. A segment a–b counts when (a.x > x) ≠ (b.x > x) and its height at x is above |y|.
 */
export function belowMaskitBoundary(x: number, y: number, maxQ: number): boolean {
  const { xs, ys } = polyline(maxQ);
  const fx = foldPeriod(x);
  const fy = Math.abs(y);
  let below = false;
  for (let i = 1; i < xs.length; i++) {
    const [ax, ay, bx, by] = [xs[i - 1], ys[i - 1], xs[i], ys[i]];
    if (ax > fx !== bx > fx && ay + ((fx - ax) * (by - ay)) / (bx - ax) > fy) below = !below;
  }
  return below;
}

/** Squared distance from (x, y) to the segment a–b. */
function segmentDistance2(x: number, y: number, ax: number, ay: number, bx: number, by: number): number {
  const dx = bx - ax;
  const dy = by - ay;
  const t = Math.min(1, Math.max(0, ((x - ax) * dx + (y - ay) * dy) / (dx * dx + dy * dy)));
  const ex = x - ax - t * dx;
  const ey = y - ay - t * dy;
  return ex * ex + ey * ey;
}

/**
 * The distance from μ to the boundary polyline (q ≤ maxQ): from (x folded, |y|) to the polyline
 * and its translates by ±2 (the folded point may be nearest the next period's end segments). A
 * segment whose x-range is farther than the best so far is skipped (it cannot be nearer).
 */
export function maskitBoundaryDistance(x: number, y: number, maxQ: number): number {
  const { xs, ys } = polyline(maxQ);
  const fx = foldPeriod(x);
  const fy = Math.abs(y);
  let best = Number.POSITIVE_INFINITY;
  for (const shift of [-2, 0, 2]) {
    const px = fx + shift;
    for (let i = 1; i < xs.length; i++) {
      const gap = Math.max(xs[i] - px, px - xs[i - 1], 0); // xs decrease along the polyline
      if (gap * gap >= best) continue;
      best = Math.min(best, segmentDistance2(px, fy, xs[i - 1], ys[i - 1], xs[i], ys[i]));
    }
  }
  return Math.sqrt(best);
}
