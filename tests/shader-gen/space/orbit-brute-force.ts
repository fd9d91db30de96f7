/**
 * Brute-force orbits for the tracer tests: the orbit spheres w(seed) of words up to a length,
 * their distance from a point, and a ray's first hit among them. Exact for every enumerated sphere;
 * the enumeration is a finite part of the orbit, so its distance is ≥ the true orbit distance.
 */
import type { Plane, Sphere } from '../../../nodes/geometry/space/sphere.ts';
import { invertSphere, reflectInPlane } from '../../../nodes/geometry/space/sphere.ts';
import { dist3, type Vec3 } from '../../../nodes/geometry/space/vec3.ts';

/**
 * All w(seed) for reduced words w of length ≤ maxLength in `mirrors` (involutions: no letter twice
 * in a row), `image` giving the image of a ball under one of them (null: not a ball, dropped).
 */
function wordOrbit<M>(
  mirrors: readonly M[],
  seeds: readonly Sphere[],
  maxLength: number,
  image: (m: M, s: Sphere) => Sphere | null,
): Sphere[] {
  const all: Sphere[] = [...seeds];
  let level = seeds.map((s) => ({ s, last: -1 }));
  for (let k = 0; k < maxLength; k++) {
    const next: { s: Sphere; last: number }[] = [];
    for (const { s, last } of level) {
      mirrors.forEach((m, i) => {
        if (i === last) return;
        const img = image(m, s);
        if (img) next.push({ s: img, last: i });
      });
    }
    all.push(...next.map((n) => n.s));
    level = next;
  }
  return all;
}

/** All w(seed) for reduced words w in the inversions of length ≤ maxLength. */
export const inversionOrbit = (mirrors: readonly Sphere[], seeds: readonly Sphere[], maxLength: number) =>
  wordOrbit(mirrors, seeds, maxLength, (m, s) => {
    const img = invertSphere(m, s);
    return img.kind === 'sphere' ? img.sphere : null;
  });

/** Images of the seeds under G^k, |k| ≤ n, G = I_S2 ∘ I_S1 (a two-sphere generator). */
export function generatorOrbit(s1: Sphere, s2: Sphere, seeds: readonly Sphere[], n: number): Sphere[] {
  const apply = (order: readonly Sphere[], s: Sphere): Sphere | null => {
    let cur = s;
    for (const m of order) {
      const img = invertSphere(m, cur);
      if (img.kind !== 'sphere') return null;
      cur = img.sphere;
    }
    return cur;
  };
  const all: Sphere[] = [...seeds];
  for (const order of [
    [s1, s2],
    [s2, s1],
  ]) {
    let level: Sphere[] = [...seeds];
    for (let k = 0; k < n; k++) {
      level = level.flatMap((s) => apply(order, s) ?? []);
      all.push(...level);
    }
  }
  return all;
}

/** An involution of a mixed scene: inversion in a sphere or reflection in a plane. */
export type Involution = { readonly sphere: Sphere } | { readonly plane: Plane };

/**
 * The image of ball b under one involution, or null where it is not a ball (an inversion centre on
 * or inside b: the image is a half-space or a ball's outside).
 */
export function involutionImage(m: Involution, b: Sphere): Sphere | null {
  if ('plane' in m) return { center: reflectInPlane(m.plane, b.center).x, radius: b.radius };
  if (dist3(m.sphere.center, b.center) <= b.radius) return null;
  const img = invertSphere(m.sphere, b);
  return img.kind === 'sphere' ? img.sphere : null;
}

/** All w(seed) for reduced words w of length ≤ maxLength in mixed involutions (sphere inversions, plane reflections). */
export const involutionOrbit = (
  mirrors: readonly Involution[],
  seeds: readonly Sphere[],
  maxLength: number,
) => wordOrbit(mirrors, seeds, maxLength, involutionImage);

/**
 * Images of the seeds under G^k, |k| ≤ n, for a generator G that is a chain of inversions
 * (`chain` in the order applied, G⁻¹ being the reversed chain): G^k(seed) exactly, each inversion
 * mapping a ball to a ball. A power whose image is not a ball (an inversion centre on or inside
 * an intermediate ball) is left out, and so are the higher powers on that side.
 */
export function chainOrbit(chain: readonly Sphere[], seeds: readonly Sphere[], n: number): Sphere[] {
  const apply = (order: readonly Sphere[], s: Sphere): Sphere | null => {
    let cur: Sphere | null = s;
    for (const sphere of order) {
      cur = cur && involutionImage({ sphere }, cur);
    }
    return cur;
  };
  const all: Sphere[] = [...seeds];
  for (const order of [chain, [...chain].reverse()]) {
    let level: Sphere[] = [...seeds];
    for (let k = 0; k < n; k++) {
      level = level.flatMap((s) => apply(order, s) ?? []);
      all.push(...level);
    }
  }
  return all;
}

/** Images of the seeds under G^k, |k| ≤ n, for an isometry G (and its inverse) given on points. */
export function isometryOrbit(
  forward: (x: Vec3) => Vec3,
  backward: (x: Vec3) => Vec3,
  seeds: readonly Sphere[],
  n: number,
): Sphere[] {
  const all: Sphere[] = [...seeds];
  for (const map of [forward, backward]) {
    let level: Sphere[] = [...seeds];
    for (let k = 0; k < n; k++) {
      level = level.map((s) => ({ center: map(s.center), radius: s.radius }));
      all.push(...level);
    }
  }
  return all;
}

export const bruteDistance = (spheres: readonly Sphere[], x: Vec3): number =>
  Math.min(...spheres.map((s) => Math.max(0, dist3(x, s.center) - s.radius)));

/** The first t > 0 where o + t·d (d unit) meets one of the spheres, or null. */
export function bruteRayHit(spheres: readonly Sphere[], o: Vec3, d: Vec3): number | null {
  let best: number | null = null;
  for (const s of spheres) {
    const ox = o[0] - s.center[0];
    const oy = o[1] - s.center[1];
    const oz = o[2] - s.center[2];
    const b = ox * d[0] + oy * d[1] + oz * d[2];
    const disc = b * b - (ox * ox + oy * oy + oz * oz - s.radius * s.radius);
    if (disc < 0) continue;
    const t = -b - Math.sqrt(disc);
    if (t > 0 && (best === null || t < best)) best = t;
  }
  return best;
}
