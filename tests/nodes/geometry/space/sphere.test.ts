import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import {
  invertInSphere,
  invertSphere,
  planeSignedDistance,
  reflectInPlane,
  type Sphere,
  sphereFromFourPoints,
  sphereThroughInverses,
} from '../../../../nodes/geometry/space/sphere.ts';
import { add3, dist3, len2v3, scale3, sub3, type Vec3 } from '../../../../nodes/geometry/space/vec3.ts';
import { nestedPair, point3, SEED, sphere, unit3 } from './arbitraries.ts';

const onSphere = (s: Sphere, dir: Vec3): Vec3 => add3(s.center, scale3(dir, s.radius));

describe('invertInSphere (x ↦ c + r²(x−c)/|x−c|², factor r²/|x−c|²)', () => {
  it('is an involution, fixes the sphere, swaps the sides', () => {
    fc.assert(
      fc.property(sphere, point3, (s, x) => {
        const d = dist3(x, s.center);
        fc.pre(d > 1e-2);
        const y = invertInSphere(s, x)!;
        expect(dist3(y.x, s.center) * d).toBeCloseTo(s.radius ** 2, 9);
        const back = invertInSphere(s, y.x)!;
        expect(dist3(back.x, x)).toBeLessThan(1e-9 * Math.max(1, dist3(y.x, s.center)));
        expect(y.factor * back.factor).toBeCloseTo(1, 9);
      }),
      SEED,
    );
    expect(invertInSphere({ center: [1, 2, 3], radius: 1 }, [1, 2, 3])).toBeNull();
  });

  it('its factor is the local length scale (finite differences in every direction)', () => {
    fc.assert(
      fc.property(sphere, point3, unit3, (s, x, u) => {
        fc.pre(dist3(x, s.center) > 0.3);
        const h = 1e-6;
        const a = invertInSphere(s, x)!;
        const b = invertInSphere(s, add3(x, scale3(u, h)))!;
        expect(dist3(a.x, b.x) / h / a.factor).toBeCloseTo(1, 4);
      }),
      SEED,
    );
  });
});

describe('reflectInPlane (x − 2((x−q)·n)n, factor 1)', () => {
  it('is an involution that swaps the sides and keeps the plane', () => {
    fc.assert(
      fc.property(point3, unit3, point3, (q, n, x) => {
        const p = { point: q, normal: n };
        const y = reflectInPlane(p, x);
        expect(y.factor).toBe(1);
        expect(planeSignedDistance(p, y.x)).toBeCloseTo(-planeSignedDistance(p, x), 9);
        expect(dist3(reflectInPlane(p, y.x).x, x)).toBeLessThan(1e-9);
      }),
      SEED,
    );
  });
});

describe('invertSphere (image of a sphere in a sphere)', () => {
  it('maps every point of S onto the image sphere, and the ball onto its region', () => {
    fc.assert(
      fc.property(sphere, sphere, unit3, (t, s, u) => {
        const delta = len2v3(sub3(s.center, t.center)) - s.radius ** 2;
        fc.pre(Math.abs(delta) > 0.05);
        const img = invertSphere(t, s);
        expect(img.kind).toBe('sphere');
        if (img.kind !== 'sphere') return;
        const y = invertInSphere(t, onSphere(s, u));
        fc.pre(y !== null);
        expect(dist3(y!.x, img.sphere.center)).toBeCloseTo(img.sphere.radius, 6);
      }),
      SEED,
    );
  });

  it('a sphere through the inversion centre goes to a plane whose region is the image of the ball', () => {
    const t: Sphere = { center: [0, 0, 0], radius: 2 };
    const s: Sphere = { center: [0, 0, 1], radius: 1 };
    const img = invertSphere(t, s);
    expect(img.kind).toBe('plane');
    if (img.kind !== 'plane') return;
    // the top point (0,0,2) maps to (0,0,2): the plane is z = 2; the ball's centre maps to z = 4
    expect(img.plane.point[2]).toBeCloseTo(2, 12);
    expect(planeSignedDistance(img.plane, [5, 1, 2])).toBeCloseTo(0, 12);
    expect(planeSignedDistance(img.plane, invertInSphere(t, s.center)!.x)).toBeLessThan(0);
  });
});

describe('sphereFromFourPoints (circumsphere)', () => {
  it('passes through four points drawn on a sphere', () => {
    fc.assert(
      fc.property(sphere, fc.tuple(unit3, unit3, unit3, unit3), (s, [a, b, c, d]) => {
        const pts = [a, b, c, d].map((u) => onSphere(s, u));
        const res = sphereFromFourPoints(pts[0]!, pts[1]!, pts[2]!, pts[3]!);
        fc.pre(res.ok); // nearly coplanar draws are rejected, tested below
        if (!res.ok) return;
        for (const p of pts) expect(dist3(p, res.value.center)).toBeCloseTo(res.value.radius, 6);
      }),
      SEED,
    );
  });

  it('rejects coplanar and coincident points with a message instead of NaN', () => {
    const coplanar = sphereFromFourPoints([0, 0, 0], [1, 0, 0], [0, 1, 0], [3, 7, 0]);
    expect(coplanar).toEqual({ ok: false, error: expect.stringMatching(/coplanar/) });
    const same = sphereFromFourPoints([1, 1, 1], [1, 1, 1], [1, 1, 1], [1, 1, 1]);
    expect(same).toEqual({ ok: false, error: expect.stringMatching(/coincide/) });
  });
});

describe('sphereThroughInverses (Sphere(P, P′, P″, Q) of §5.1.2)', () => {
  it('passes through P, I_S1(P), I_S2(P), Q and is orthogonal to S1 and S2', () => {
    fc.assert(
      fc.property(nestedPair, point3, point3, ({ s1, s2 }, p, q) => {
        const res = sphereThroughInverses(s1, s2, p, q);
        fc.pre(res.ok && res.value.radius < 1e4);
        if (!res.ok) return;
        const s3 = res.value;
        for (const x of [p, q, invertInSphere(s1, p)!.x, invertInSphere(s2, p)!.x]) {
          expect(dist3(x, s3.center) / s3.radius).toBeCloseTo(1, 6);
        }
        // orthogonal: |c − c3|² = r² + r3²
        for (const s of [s1, s2]) {
          const d2 = len2v3(sub3(s.center, s3.center));
          expect(d2 / (s.radius ** 2 + s3.radius ** 2)).toBeCloseTo(1, 6);
        }
      }),
      SEED,
    );
  });

  it('fails with a message when P is on the line of centres (the points are coplanar)', () => {
    const res = sphereThroughInverses(
      { center: [0, 0, 0], radius: 1 },
      { center: [0.2, 0, 0], radius: 3 },
      [0.5, 0, 0],
      [0, 1, 0],
    );
    expect(res.ok).toBe(false);
  });
});
