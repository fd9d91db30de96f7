/**
 * Tile edges near ∞. The edge width uses d/s (docs/math.md "Length scale"), d = the final point's
 * distance to the nearest boundary. When every element acts on a bounded disk, the tile contains a
 * neighbourhood of ∞, and a point that lands far out (a point near an inversion centre) has a large
 * d that still shrinks to d/s → 0 at the centre: a tiny dot of edge colour at every centre.
 * The fix measures the distance in the chart inverted in the bounding circle (o, ρ) of all
 * boundaries, where ∞ is an ordinary point: there the boundaries lie outside the disk and the
 * final point at R = |q − o| > ρ sits ρ − ρ²/R from them, which the inversion's conformal factor
 * ρ²/R² stretches back to (R − ρ)·R/ρ. The edge distance is max(d, that) / s.
 */
import type { DiskRegion, SceneElement } from '../nodes/core/scene.ts';
import type { Circle } from '../nodes/core/values.ts';

/** The inside disks of an element, or null when one of its insides is unbounded. */
function insideDisks(e: SceneElement): readonly Circle[] | null {
  const disk = (d: DiskRegion) => (d.outside ? null : { c: d.c, r: d.r });
  const both = (a: DiskRegion, b: DiskRegion) => {
    const x = disk(a);
    const y = disk(b);
    return x && y ? [x, y] : null;
  };
  switch (e.kind) {
    case 'inversion':
      return [{ c: e.c, r: e.r }];
    case 'mobius':
    case 'loxodromic':
      return both(e.a, e.b);
    case 'mobius-matrix':
      return both(e.forward, e.backward);
    default:
      return null;
  }
}

/**
 * The circle (o, ρ) holding every element's inside, o the mean of the disk centres; null when
 * some inside is unbounded (a line, a strip, an outside region) or there are no elements.
 */
export function farDisk(elements: readonly SceneElement[]): Circle | null {
  const disks: Circle[] = [];
  for (const e of elements) {
    const d = insideDisks(e);
    if (!d) return null;
    disks.push(...d);
  }
  if (disks.length === 0) return null;
  const ox = disks.reduce((t, d) => t + d.c[0], 0) / disks.length;
  const oy = disks.reduce((t, d) => t + d.c[1], 0) / disks.length;
  const rho = Math.max(...disks.map((d) => Math.hypot(d.c[0] - ox, d.c[1] - oy) + d.r));
  return { c: [ox, oy], r: rho };
}

/**
 * How far the limit set lies beyond a tile edge, in the tile's frame: the smallest radius of the
 * elements' bounded inside disks (the limit set lies inside them); null when there is none (only
 * lines and strips: no limit set at a finite distance). The limit-set colouring estimates the
 * distance to the limit set as (edge distance + reach) / s.
 */
export function limitReach(elements: readonly SceneElement[]): number | null {
  let reach = Number.POSITIVE_INFINITY;
  const take = (d: DiskRegion) => {
    if (!d.outside) reach = Math.min(reach, d.r);
  };
  for (const e of elements) {
    if (e.kind === 'inversion') reach = Math.min(reach, e.r);
    else if (e.kind === 'mobius' || e.kind === 'loxodromic') {
      take(e.a);
      take(e.b);
    } else if (e.kind === 'mobius-matrix') {
      take(e.forward);
      take(e.backward);
    } else if (e.kind === 'maskit')
      reach = Math.min(reach, 1); // its isometric circles' radius
    // The slice's edge distance is already the distance to what it paints in the limit colour.
    else if (e.kind === 'maskit-slice') reach = 0;
  }
  return Number.isFinite(reach) ? reach : null;
}

/** Distance from (x, y) to the boundaries measured through the far chart: R > ρ ? (R − ρ)·R/ρ : 0. */
export function farDistance(far: Circle, x: number, y: number): number {
  const dx = x - far.c[0];
  const dy = y - far.c[1];
  const big = Math.sqrt(dx * dx + dy * dy);
  return big > far.r ? ((big - far.r) * big) / far.r : 0;
}
