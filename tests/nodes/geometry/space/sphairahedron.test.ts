/**
 * Cube-type sphairahedra (docs/math-3d.md "Sphairahedra (paper §5.3)"): the angle table makes every
 * vertex ideal; the built faces meet at the claimed dihedral angles π/n, measured at actual points
 * of the edges; the inversion centre check refuses centres that would turn a face inside out; the
 * finite faces are the inverted infinite faces with the same angles; the seeds sit on the far side.
 */
import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import { iis3d } from '../../../../nodes/geometry/space/iis-3d.ts';
import {
  CUBE_TYPES,
  defaultInversionSphere,
  finiteElements,
  finiteSphairahedron,
  type InfiniteSphairahedron,
  infiniteElements,
  infiniteSeedBox,
  infiniteSphairahedron,
  inversionCentreProblem,
  SPHAIRAHEDRON_TYPES,
  type SphairahedronType,
} from '../../../../nodes/geometry/space/sphairahedron.ts';
import {
  invertInSphere,
  type Plane,
  planeSignedDistance,
  type Sphere,
} from '../../../../nodes/geometry/space/sphere.ts';
import {
  add3,
  cross3,
  dist3,
  dot3,
  normalize3,
  scale3,
  sub3,
  type Vec3,
} from '../../../../nodes/geometry/space/vec3.ts';
import { real, SEED, unit3 } from './arbitraries.ts';

const idx = (k: number) => ((k % 3) + 3) % 3;
const angle = (n: number) => Math.PI / n;

/** A unit vector perpendicular to u. */
const perp = (u: Vec3): Vec3 => normalize3(cross3(u, Math.abs(u[0]) < 0.9 ? [1, 0, 0] : [0, 1, 0]));

/** Interior angle from the outward normals o1, o2 of the region at an edge point: π − ∠(o1, o2). */
const interior = (o1: Vec3, o2: Vec3) => Math.PI - Math.acos(Math.max(-1, Math.min(1, dot3(o1, o2))));

/** The region keeps the plane's normal side: outward normal −n. */
function planePlaneAngle(a: Plane, b: Plane): number {
  return interior(scale3(a.normal, -1), scale3(b.normal, -1));
}

/** At a point p of the circle plane ∩ sphere: outward normals −n (plane) and (c − p)/r (outside the ball). */
function planeSphereAngle(pl: Plane, s: Sphere): number {
  const sd = planeSignedDistance(pl, s.center);
  const foot = sub3(s.center, scale3(pl.normal, sd));
  const p = add3(foot, scale3(perp(pl.normal), Math.sqrt(s.radius ** 2 - sd ** 2)));
  expect(Math.abs(dist3(p, s.center) - s.radius)).toBeLessThan(1e-9);
  return interior(scale3(pl.normal, -1), scale3(sub3(s.center, p), 1 / s.radius));
}

/** At a point p of the circle where two spheres meet; the region is outside both balls. */
function sphereSphereAngle(s1: Sphere, s2: Sphere): number {
  const d = dist3(s1.center, s2.center);
  const u = normalize3(sub3(s2.center, s1.center));
  const a = (d * d + s1.radius ** 2 - s2.radius ** 2) / (2 * d);
  const p = add3(add3(s1.center, scale3(u, a)), scale3(perp(u), Math.sqrt(s1.radius ** 2 - a * a)));
  expect(Math.abs(dist3(p, s2.center) - s2.radius)).toBeLessThan(1e-9);
  return interior(scale3(sub3(s1.center, p), 1 / s1.radius), scale3(sub3(s2.center, p), 1 / s2.radius));
}

/** The 12 edges of the cube type with their claimed angle (face indices: F1..F3 = 0..2, S1..S3 = 3..5). */
function claimedEdges(t: SphairahedronType): [number, number, number][] {
  const out: [number, number, number][] = [];
  if (t.kind === 'pentahedral-prism') {
    // S_c = 3 (corner V1), S_m = 4 (central): the prism's 9 edges.
    for (let k = 0; k < 3; k++) {
      out.push([idx(k + 1), idx(k + 2), angle(t.prism[k])]);
      out.push([4, k, angle(t.central[k])]);
    }
    out.push([3, 1, angle(t.corner[0])], [3, 2, angle(t.corner[1])], [3, 4, angle(t.sphereSphere)]);
    return out;
  }
  for (let k = 0; k < 3; k++) {
    out.push([idx(k + 1), idx(k + 2), angle(t.prism[k])]);
    out.push([3 + k, idx(k + 1), angle(t.spherePlane[k][0])]);
    out.push([3 + k, idx(k + 2), angle(t.spherePlane[k][1])]);
    out.push([3 + k, 3 + idx(k + 1), angle(t.sphereSphere[k])]);
  }
  return out;
}

const shapeParams = fc.record({
  type: fc.constantFrom(...SPHAIRAHEDRON_TYPES),
  zb: real(-0.8, 0.8),
  zc: real(-0.8, 0.8),
});

const built = shapeParams
  .map(({ type, zb, zc }) => infiniteSphairahedron(type, zb, zc))
  .filter((r) => r.ok)
  .map((r) => (r as { ok: true; value: InfiniteSphairahedron }).value);

const centroid = (inf: InfiniteSphairahedron): Vec3 =>
  scale3(add3(add3(inf.corners[0], inf.corners[1]), inf.corners[2]), 1 / 3);

describe('the cube-type angle table', () => {
  it.each(CUBE_TYPES.map((t) => [t.id, t] as const))(
    '%s: every vertex is ideal (its angles sum to π)',
    (_, t) => {
      const sum = (...ns: number[]) => ns.reduce((s, n) => s + 1 / n, 0);
      expect(sum(...t.prism)).toBeCloseTo(1, 12); // the vertex at infinity: a Euclidean triangle
      for (let k = 0; k < 3; k++) {
        expect(sum(t.prism[k], ...t.spherePlane[k])).toBeCloseTo(1, 12); // F, F, S_k on the edge at V_k
        const i = k;
        const j = idx(k + 1);
        const m = idx(k + 2); // the plane S_i and S_j both meet
        const withM = (s: number) => t.spherePlane[s][idx(m - s) === 1 ? 0 : 1];
        expect(sum(withM(i), withM(j), t.sphereSphere[k])).toBeCloseTo(1, 12); // S_i, S_j, F_m
      }
      expect(sum(...t.sphereSphere)).toBeCloseTo(1, 12); // S1, S2, S3
      expect(infiniteSphairahedron(t, 0, 0).ok).toBe(true);
    },
  );
});

describe('the pentahedral prism angle table', () => {
  const prisms = SPHAIRAHEDRON_TYPES.filter((t) => t.kind === 'pentahedral-prism');
  it.each(prisms.map((t) => [t.id, t] as const))('%s: every vertex is ideal', (_, t) => {
    const sum = (...ns: number[]) => ns.reduce((s, n) => s + 1 / n, 0);
    expect(sum(...t.prism)).toBeCloseTo(1, 12); // the vertex at infinity
    expect(sum(t.prism[0], ...t.corner)).toBeCloseTo(1, 12); // F2, F3, S_c on the edge at V1
    expect(sum(t.prism[1], t.central[0], t.central[2])).toBeCloseTo(1, 12); // F1, F3, S_m at V2
    expect(sum(t.prism[2], t.central[0], t.central[1])).toBeCloseTo(1, 12); // F1, F2, S_m at V3
    expect(sum(t.corner[0], t.central[1], t.sphereSphere)).toBeCloseTo(1, 12); // F2, S_c, S_m
    expect(sum(t.corner[1], t.central[2], t.sphereSphere)).toBeCloseTo(1, 12); // F3, S_c, S_m
    expect(infiniteSphairahedron(t, 0.6, 0).ok).toBe(true);
  });

  it('prism 333, all π/3: the corner sphere has radius zb²/3 and the central one radius 1', () => {
    const t = SPHAIRAHEDRON_TYPES.find((x) => x.id === 'prism-333-a')!;
    fc.assert(
      fc.property(real(0.3, 1.4), (zb) => {
        const r = infiniteSphairahedron(t, zb, 0);
        if (!r.ok) throw new Error(r.error);
        expect(r.value.spheres[0].radius).toBeCloseTo((zb * zb) / 3, 10);
        expect(r.value.spheres[1].radius).toBeCloseTo(1, 10);
      }),
      SEED,
    );
  });
});

describe('infiniteSphairahedron', () => {
  it('prism 333, all π/3: the radii r = ½ + zb·zc/3, ½ + (zb² − zb·zc)/3, ½ + (zc² − zb·zc)/3', () => {
    const t = CUBE_TYPES.find((x) => x.id === 'cube-333-a')!;
    fc.assert(
      fc.property(real(-0.6, 0.6), real(-0.6, 0.6), (zb, zc) => {
        const r = infiniteSphairahedron(t, zb, zc);
        if (!r.ok) throw new Error(r.error);
        const radii = r.value.spheres.map((s) => s.radius);
        expect(radii[0]).toBeCloseTo(0.5 + (zb * zc) / 3, 10);
        expect(radii[1]).toBeCloseTo(0.5 + (zb * zb - zb * zc) / 3, 10);
        expect(radii[2]).toBeCloseTo(0.5 + (zc * zc - zb * zc) / 3, 10);
      }),
      SEED,
    );
  });

  it('adjacent faces meet at the claimed angles π/n (measured at points of the edges)', () => {
    fc.assert(
      fc.property(built, (inf) => {
        const faces = [...inf.planes, ...inf.spheres];
        for (const [a, b, claimed] of claimedEdges(inf.type)) {
          const fa = faces[a];
          const fb = faces[b];
          const got =
            a < 3 && b < 3
              ? planePlaneAngle(fa as Plane, fb as Plane)
              : b < 3
                ? planeSphereAngle(fb as Plane, fa as Sphere)
                : sphereSphereAngle(fa as Sphere, fb as Sphere);
          expect(got).toBeCloseTo(claimed, 9);
        }
      }),
      SEED,
    );
  });

  it('each sphere touches the prism edges of its ideal vertices there', () => {
    fc.assert(
      fc.property(built, (inf) => {
        const touches = (s: Sphere, k: number) =>
          expect(Math.hypot(s.center[0] - inf.corners[k][0], s.center[1] - inf.corners[k][1])).toBeCloseTo(
            s.radius,
            10,
          );
        if (inf.type.kind === 'cube') inf.spheres.forEach(touches);
        else {
          touches(inf.spheres[0], 0);
          touches(inf.spheres[1], 1);
          touches(inf.spheres[1], 2);
        }
      }),
      SEED,
    );
  });

  it('refuses shape parameters outside the parameter space, with a message', () => {
    const r = infiniteSphairahedron(CUBE_TYPES[0], 3, -3);
    expect(r.ok).toBe(false);
    if (!r.ok) expect(r.error).toMatch(/radius|reaches|hole/);
  });
});

/** A valid centre: above the highest sphere top, strictly inside the triangle. */
const validCentre = fc
  .tuple(built, real(0.05, 0.9), real(0.05, 0.9), real(0.05, 3))
  .map(([inf, u, v, up]): [InfiniteSphairahedron, Vec3] => {
    const [a, b, c] = inf.corners;
    const uu = u * (1 - v * 0.999);
    const vv = v * (1 - u) * 0.999;
    const p = add3(add3(scale3(a, uu), scale3(b, vv)), scale3(c, 1 - uu - vv));
    const top = Math.max(...inf.spheres.map((s) => s.center[2] + s.radius));
    return [inf, [p[0], p[1], top + up]];
  })
  .filter(([inf, o]) => inf.planes.every((pl) => planeSignedDistance(pl, o) > 1e-3));

describe('the inversion centre check', () => {
  it('accepts centres in the infinite sphairahedron above the spheres', () => {
    fc.assert(
      fc.property(validCentre, ([inf, o]) => {
        expect(inversionCentreProblem(inf, o)).toBeNull();
      }),
      SEED,
    );
  });

  it('refuses a centre inside a ball, outside the prism, or under the spheres', () => {
    fc.assert(
      fc.property(built, fc.integer({ min: 0, max: 2 }), unit3, real(0, 0.95), (inf, k, dir, f) => {
        const s = inf.spheres[k % inf.spheres.length];
        const inBall = add3(s.center, scale3(dir, f * s.radius));
        expect(inversionCentreProblem(inf, inBall)).toMatch(/inside sphere S|outside the prism/);
        const c = centroid(inf);
        const outside = add3(c, scale3(inf.planes[k].normal, -3));
        expect(inversionCentreProblem(inf, [outside[0], outside[1], 5])).toMatch(/outside the prism/);
        // Below every ball, under the centroid (which the balls cover).
        const bottom = Math.min(...inf.spheres.map((sp) => sp.center[2] - sp.radius));
        const below: Vec3 = [c[0], c[1], bottom - 0.5 - f];
        expect(inversionCentreProblem(inf, below)).toMatch(/under sphere S/);
      }),
      SEED,
    );
  });
});

describe('finiteSphairahedron', () => {
  it('its faces are the inversions of the infinite faces, meeting at the same angles', () => {
    fc.assert(
      fc.property(validCentre, real(0.3, 3), unit3, real(-3, 3), ([inf, o], R, dir, t) => {
        const inv: Sphere = { center: o, radius: R };
        const fin = finiteSphairahedron(inf, inv);
        if (!fin.ok) throw new Error(fin.error);
        const { spheres } = fin.value;
        // Points of each infinite face land on the corresponding finite sphere.
        inf.planes.forEach((pl, k) => {
          const q = add3(add3(pl.point, scale3(perp(pl.normal), t)), scale3([0, 0, 1], t * 0.7));
          const y = invertInSphere(inv, q)!.x;
          expect(dist3(y, spheres[k].center) / spheres[k].radius).toBeCloseTo(1, 8);
        });
        inf.spheres.forEach((s, k) => {
          const y = invertInSphere(inv, add3(s.center, scale3(dir, s.radius)))!.x;
          expect(dist3(y, spheres[3 + k].center) / spheres[3 + k].radius).toBeCloseTo(1, 8);
        });
        for (const [a, b, claimed] of claimedEdges(inf.type))
          expect(sphereSphereAngle(spheres[a], spheres[b])).toBeCloseTo(claimed, 7);
      }),
      { ...SEED, numRuns: 100 },
    );
  });

  it('refuses an inversion centre that would turn a face inside out', () => {
    const inf = infiniteSphairahedron(CUBE_TYPES[0], 0.2, -0.1);
    if (!inf.ok) throw new Error(inf.error);
    const s = inf.value.spheres[1];
    const r = finiteSphairahedron(inf.value, { center: s.center, radius: 1 });
    expect(r.ok).toBe(false);
    if (!r.ok) expect(r.error).toMatch(/inside out/);
  });
});

describe('the seeds lie on the far side of the limit set', () => {
  it('infinite: the IIS takes points far below into the seed box and points far above elsewhere', () => {
    fc.assert(
      fc.property(built, real(-1.5, 1.5), real(-1.5, 1.5), (inf, x, y) => {
        const elements = infiniteElements(inf);
        const box = infiniteSeedBox(inf);
        const inBox = (p: Vec3) => p.every((v, i) => Math.abs(v - box.center[i]) <= box.halfSize[i]);
        const low = iis3d(elements, [x, y, inf.floorTop - 2], 200);
        expect(low.escaped && inBox(low.point)).toBe(true);
        const high = iis3d(elements, [x, y, 20], 200);
        expect(high.escaped && !inBox(high.point)).toBe(true);
      }),
      { ...SEED, numRuns: 100 },
    );
  });

  it('finite: the seed ball is the image of the region below the floor, the centre side is never in it', () => {
    fc.assert(
      fc.property(validCentre, real(-1, 1), real(-1, 1), ([inf, o], x, y) => {
        const inv: Sphere = { center: o, radius: 1.5 };
        const fin = finiteSphairahedron(inf, inv);
        if (!fin.ok) throw new Error(fin.error);
        const below = invertInSphere(inv, [x, y, inf.floorTop - 0.5])!.x;
        expect(dist3(below, fin.value.seed.center)).toBeLessThan(fin.value.seed.radius);
        // Far away (the image of points near O, in the upper piece) is outside the seed.
        const far = iis3d(finiteElements(fin.value), add3(o, [0, 0, 40]), 200);
        expect(dist3(far.point, fin.value.seed.center)).toBeGreaterThan(fin.value.seed.radius);
      }),
      { ...SEED, numRuns: 100 },
    );
  });

  it('the default inversion sphere is valid for every type', () => {
    for (const t of SPHAIRAHEDRON_TYPES) {
      const inf = infiniteSphairahedron(t, t.kind === 'cube' ? 0 : 0.6, 0);
      if (!inf.ok) throw new Error(inf.error);
      expect(finiteSphairahedron(inf.value, defaultInversionSphere(inf.value)).ok).toBe(true);
    }
  });
});
