/**
 * The mirror material and environment on the CPU (shader-gen/space/reflect-3d.ts, docs/math-3d.md
 * "Mirror material"): a mirror floor shows a known ball exactly where its mirror image is, the
 * reflections 0 picture is the matte picture, Schlick's Fresnel term, and the sky seen by rays
 * that hit nothing, primary and reflected alike.
 */
import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import type { Scene3d, Seed3d } from '../../../nodes/core/scene-3d.ts';
import { dot3, normalize3, scale3, sub3, type Vec3 } from '../../../nodes/geometry/space/vec3.ts';
import { prepareTrace3d } from '../../../shader-gen/space/plan.ts';
import { environmentOf, fresnel, radiance, reflect3 } from '../../../shader-gen/space/reflect-3d.ts';
import { renderScene3d } from '../../../shader-gen/space/render-3d.ts';
import { traceRay } from '../../../shader-gen/space/trace-3d.ts';
import { MIRROR_FIG11, scene3d, seedSphere } from './scenes-3d.ts';

const BLUE = [0, 0, 1] as const;
const BALL = { center: [0, 0, 1] as Vec3, radius: 0.5 };
/** A perfect white mirror floor (the top of a wide box, z = 0) under a red matte ball, a blue background. */
const FLOOR: Seed3d = {
  kind: 'box',
  nodeId: 'floor',
  center: [0, 0, -0.5],
  halfSize: [6, 6, 0.5],
  color: [1, 1, 1],
  reflectivity: 1,
};
const MIRROR_FLOOR = scene3d([], [FLOOR, seedSphere(BALL.center, BALL.radius, [1, 0, 0], 'ball')], {
  background: BLUE,
  lighting: {
    direction: [0.3, -0.4, 1],
    ambient: 0.5,
    diffuse: 0.5,
    specular: 0,
    shininess: 32,
    occlusion: 0,
    shadow: 0,
  },
  reflections: 1,
});

/** Distance from c to the ray o + t·d (d unit), t ≥ 0. */
function rayDistance(o: Vec3, d: Vec3, c: Vec3): number {
  const t = Math.max(0, dot3(sub3(c, o), d));
  const q = sub3(c, [o[0] + d[0] * t, o[1] + d[1] * t, o[2] + d[2] * t]);
  return Math.hypot(q[0], q[1], q[2]);
}

describe('mirror material (CPU reference)', () => {
  it('a mirror floor shows the ball at its mirror image below the floor, and the background elsewhere', () => {
    const plan = prepareTrace3d(MIRROR_FLOOR);
    const env = environmentOf(MIRROR_FLOOR);
    const eye: Vec3 = [0, -4, 1.5];
    const image: Vec3 = [0, 0, -1]; // the ball mirrored in z = 0
    const angle = 1e-3;
    let reflected = 0;
    let sky = 0;
    for (let x = -1.5; x <= 1.5; x += 0.1) {
      for (let y = -2.5; y <= 1.5; y += 0.1) {
        const d = normalize3(sub3([x, y, 0], eye));
        const toFloor = -eye[2] / d[2];
        // Skip rays that meet the ball itself before the floor, and the image's silhouette.
        if (
          rayDistance(eye, d, BALL.center) < BALL.radius + 0.05 &&
          dot3(sub3(BALL.center, eye), d) < toFloor
        )
          continue;
        const miss = rayDistance(eye, d, image) - BALL.radius;
        if (Math.abs(miss) < 0.03) continue;
        const first = traceRay(plan, eye, d, angle);
        expect(first.seed, `floor at ${x}, ${y}`).toBe(0);
        const c = radiance(plan, env, eye, d, angle, first);
        if (miss < 0) {
          reflected++;
          expect(c[0], `red ball seen at ${x}, ${y}`).toBeGreaterThan(0.05);
          expect(c[2]).toBeLessThan(1e-9);
        } else {
          sky++;
          c.forEach((v, k) => {
            expect(v, `background seen at ${x}, ${y}`).toBeCloseTo(BLUE[k]!, 9);
          });
        }
      }
    }
    expect(reflected).toBeGreaterThan(20);
    expect(sky).toBeGreaterThan(100);
  });

  it('reflections 0 draws the mirrors matte: the picture of the same scene without mirrors', () => {
    const matte: Scene3d = {
      ...MIRROR_FIG11,
      seeds: MIRROR_FIG11.seeds.map(({ reflectivity: _, ...s }) => s),
    };
    const a = renderScene3d({ ...MIRROR_FIG11, reflections: 0 }, 32, 24);
    const b = renderScene3d(matte, 32, 24);
    expect(a.data).toEqual(b.data);
    // … and with reflections the mirror looks different (the test can fail).
    const c = renderScene3d(MIRROR_FIG11, 32, 24);
    let differ = 0;
    for (let i = 0; i < c.data.length; i += 4) if (c.data[i] !== b.data[i]) differ++;
    expect(differ).toBeGreaterThan(30);
  });

  it("Schlick's Fresnel term: r head-on, 1 at grazing incidence, growing in between", () => {
    fc.assert(
      fc.property(
        fc.double({ min: 0, max: 1, noNaN: true }),
        fc.double({ min: 0, max: 1, noNaN: true }),
        (r, c) => {
          expect(fresnel(r, 1)).toBeCloseTo(r, 12);
          expect(fresnel(r, 0)).toBeCloseTo(1, 12);
          expect(fresnel(r, c)).toBeGreaterThanOrEqual(r - 1e-12);
          expect(fresnel(r, c * 0.5)).toBeGreaterThanOrEqual(fresnel(r, c) - 1e-12);
        },
      ),
      { seed: 37 },
    );
  });

  it('reflects about the normal: the tangential part is kept, the normal part turned', () => {
    const d = normalize3([0.3, -0.5, -0.8]);
    const r = reflect3(d, [0, 0, 1]);
    expect(r[0]).toBeCloseTo(d[0], 12);
    expect(r[1]).toBeCloseTo(d[1], 12);
    expect(r[2]).toBeCloseTo(-d[2], 12);
  });

  it('the sky: background at the zenith, horizon colour at the horizon, a checkered ground below', () => {
    const env = environmentOf(MIRROR_FIG11);
    const sky = MIRROR_FIG11.environment!;
    if (sky.mode !== 'sky') throw new Error('the fixture has a sky');
    const lin = (c: number) => (c <= 0.04045 ? c / 12.92 : ((c + 0.055) / 1.055) ** 2.4);
    env([0, 0, 1]).forEach((v, k) => {
      expect(v).toBeCloseTo(lin(MIRROR_FIG11.background[k]!), 12);
    });
    env([1, 0, 0]).forEach((v, k) => {
      expect(v).toBeCloseTo(lin(sky.horizon[k]!), 12);
    });
    // Straight down: ground·½ on one square, ground·½·½ on its neighbour.
    const a = env(normalize3([0.1, 0.1, -1]));
    const b = env(normalize3([-0.1, 0.1, -1]));
    expect(a[0]! / b[0]!).toBeCloseTo(2, 1);
    // A flat environment is the background everywhere.
    const flat = environmentOf({ ...MIRROR_FIG11, environment: { mode: 'flat' } });
    expect(flat(scale3([0.2, 0.3, -0.9], 1))).toEqual(flat([0, 0, 1]));
  });

  it('a primary ray that hits nothing sees the environment (the background is the sky)', () => {
    const scene: Scene3d = { ...MIRROR_FIG11, seeds: [] };
    const raster = renderScene3d(scene, 8, 8);
    // Camera slightly above the horizon looking at the origin: top rows sky, bottom rows ground.
    const top = raster.data.slice(0, 4);
    const bottom = raster.data.slice(raster.data.length - 4);
    expect(top[2]!).toBeGreaterThan(top[0]!); // sky: bluer than red
    expect(bottom[0]!).toBeGreaterThan(bottom[2]!); // ground: browner
  });
});
