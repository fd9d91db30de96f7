/**
 * Generalised circles (a circle or a line) and their images under the two mirror maps the IIS is
 * built from: inversion in a circle and reflection in a line (docs/math.md). Pure float64 maths, the
 * vector export's geometry.
 */
import type { Vec2 } from '../../nodes/core/values.ts';

export type Curve =
  | { readonly kind: 'circle'; readonly c: Vec2; readonly r: number }
  /** The line through q with unit normal n. */
  | { readonly kind: 'line'; readonly q: Vec2; readonly n: Vec2 };

/** A mirror: inversion in the circle (c, r), or reflection in the line (q, n) (n a unit vector). */
export type Mirror = Curve;

/** Below this relative size a circle "through the centre" is taken as one: its image is a line. */
const THROUGH_CENTRE_EPS = 1e-12;

/**
 * Image of `k` in the mirror `m`.
 * Circle (c1, r1) in the circle (c, r): δ = |c1−c|² − r1², k = r²/δ, c1' = c + k(c1−c), r1' = |k|·r1;
 * δ = 0 (through c) gives the line ⟂ u = (c1−c)/|c1−c| at distance r²/(2r1) from c.
 * Line at distance d > 0 from c, foot f, in the circle (c, r): the circle through c and σ(f), i.e.
 * centre c + (f−c)·r²/(2d²), radius r²/(2d); a line through c is its own image.
 * Reflection ρ(p) = p − 2((p−q)·n)n moves a circle's centre, and a line's point and normal.
 */
export function mirrorImage(m: Mirror, k: Curve): Curve {
  if (m.kind === 'line') {
    const reflect = (p: Vec2): Vec2 => {
      const h = 2 * ((p[0] - m.q[0]) * m.n[0] + (p[1] - m.q[1]) * m.n[1]);
      return [p[0] - h * m.n[0], p[1] - h * m.n[1]];
    };
    if (k.kind === 'circle') return { kind: 'circle', c: reflect(k.c), r: k.r };
    const h = 2 * (k.n[0] * m.n[0] + k.n[1] * m.n[1]);
    return { kind: 'line', q: reflect(k.q), n: [k.n[0] - h * m.n[0], k.n[1] - h * m.n[1]] };
  }
  const { c, r } = m;
  if (k.kind === 'circle') {
    const dx = k.c[0] - c[0];
    const dy = k.c[1] - c[1];
    const d2 = dx * dx + dy * dy;
    const delta = d2 - k.r * k.r;
    if (Math.abs(delta) <= THROUGH_CENTRE_EPS * Math.max(d2, k.r * k.r)) {
      const d = Math.sqrt(d2);
      const u: Vec2 = [dx / d, dy / d];
      const t = (r * r) / (2 * k.r);
      return { kind: 'line', q: [c[0] + u[0] * t, c[1] + u[1] * t], n: u };
    }
    const s = (r * r) / delta;
    return { kind: 'circle', c: [c[0] + dx * s, c[1] + dy * s], r: Math.abs(s) * k.r };
  }
  const d = (c[0] - k.q[0]) * k.n[0] + (c[1] - k.q[1]) * k.n[1];
  if (Math.abs(d) <= THROUGH_CENTRE_EPS * r) return k;
  // Foot of c on the line: f = c − d·n; f − c = −d·n.
  const t = (r * r) / (2 * d * d);
  return {
    kind: 'circle',
    c: [c[0] - d * k.n[0] * t, c[1] - d * k.n[1] * t],
    r: (r * r) / (2 * Math.abs(d)),
  };
}

/** The image of `k` under the mirrors applied in order (first mirror first). */
export const imageUnder = (mirrors: readonly Mirror[], k: Curve): Curve =>
  mirrors.reduce((acc, m) => mirrorImage(m, acc), k);

/** An element's inside: |p−c| < r (or > r when outside), or the half-plane (p−q)·n < 0. */
export type Region =
  | { readonly kind: 'disk'; readonly c: Vec2; readonly r: number; readonly outside: boolean }
  | { readonly kind: 'half-plane'; readonly q: Vec2; readonly n: Vec2 };

/**
 * Whether some of the curve lies inside the region, deeper than `tol` (world units): a curve that
 * only touches the region's boundary, or stays outside, does not meet it.
 */
export function meetsRegion(k: Curve, g: Region, tol: number): boolean {
  if (g.kind === 'half-plane') {
    if (k.kind === 'circle') return (k.c[0] - g.q[0]) * g.n[0] + (k.c[1] - g.q[1]) * g.n[1] - k.r < -tol;
    const parallel = Math.abs(k.n[0] * g.n[1] - k.n[1] * g.n[0]) < 1e-12;
    return !parallel || (k.q[0] - g.q[0]) * g.n[0] + (k.q[1] - g.q[1]) * g.n[1] < -tol;
  }
  if (k.kind === 'line') {
    const d = Math.abs((g.c[0] - k.q[0]) * k.n[0] + (g.c[1] - k.q[1]) * k.n[1]);
    return g.outside || d < g.r - tol;
  }
  const d = Math.hypot(k.c[0] - g.c[0], k.c[1] - g.c[1]);
  // Outside: all but a circle within the disk. Inside: crossing it, or within it, not around it.
  if (g.outside) return d + k.r > g.r + tol || k.r - d > g.r + tol;
  return d < g.r + k.r - tol && k.r - d < g.r - tol;
}
