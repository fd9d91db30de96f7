/**
 * Reroute points (docs/architecture.md "Frames and reroute points"): a wire from its source handle
 * through its `via` points to its target handle. Pure geometry for the editor's edge component.
 */
type P = readonly [number, number];

/** Squared distance from p to the segment ab. */
function segmentDistance2(p: P, a: P, b: P): number {
  const [dx, dy] = [b[0] - a[0], b[1] - a[1]];
  const len2 = dx * dx + dy * dy;
  // t = clamp(((p − a)·(b − a)) / |b − a|², 0, 1): the closest point is a + t(b − a).
  const t = len2 === 0 ? 0 : Math.max(0, Math.min(1, ((p[0] - a[0]) * dx + (p[1] - a[1]) * dy) / len2));
  const [x, y] = [a[0] + t * dx - p[0], a[1] + t * dy - p[1]];
  return x * x + y * y;
}

/** `via` with `p` inserted where the wire passes nearest to it (between the right two points). */
export function insertVia(source: P, via: readonly P[], target: P, p: P): [number, number][] {
  const points = [source, ...via, target];
  let best = 0;
  let bestD = Infinity;
  for (let i = 0; i + 1 < points.length; i++) {
    const d = segmentDistance2(p, points[i], points[i + 1]);
    if (d < bestD) [best, bestD] = [i, d];
  }
  const out = via.map(([x, y]) => [x, y] as [number, number]);
  out.splice(best, 0, [p[0], p[1]]);
  return out;
}

/** The SVG path through every point: straight segments (clear to read where a wire is routed). */
export const polylinePath = (points: readonly P[]): string =>
  points.map(([x, y], i) => `${i === 0 ? 'M' : 'L'} ${x} ${y}`).join(' ');
