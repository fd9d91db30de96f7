/**
 * GPU = CPU for the 3D sphere tracer in real Chromium (WebGL2 through SwiftShader): the probe
 * program of compile3d, (hit, t, depth, seed) per pixel centre, agrees with the float64 CPU tracer
 * (render-3d.ts probeScene3d) on ≥ 99.5 % of the robust pixels — those whose CPU result (hit, depth,
 * seed) is the same at the centre and a quarter pixel either way in x and y, so a silhouette that a
 * float32 rounding may move by a fraction of a pixel is not counted. Small images keep SwiftShader
 * time low. Also: the baked program draws what the uniform one draws, new values re-render without
 * a new program, and the hand-written bench tracers (tests/bench/hand-written/trace3d.ts)
 * draw the same picture as the generated one, and the colour variant shades like the CPU in every
 * colouring (the orbit colouring examples, and the measures of Fig. 34).
 */
import { describe, expect, it } from 'vitest';
import type { Scene3d } from '../../nodes/core/scene-3d.ts';
import { PALETTES } from '../../nodes/types/colour.ts';
import { cameraUniforms, compile3d } from '../../shader-gen/space/compile-3d.ts';
import { probeScene3d } from '../../shader-gen/space/render-3d.ts';
import { shadeHit } from '../../shader-gen/space/shade-3d.ts';
import { HAND_WRITTEN_3D } from '../bench/hand-written/trace3d.ts';
import { hitMissDiffer } from '../bench/trace3d.ts';
import {
  exampleScenes3d,
  FIG11,
  MOBIUS_BOX,
  PLANES,
  PSEUDO_KLEINIAN,
} from '../shader-gen/space/scenes-3d.ts';
import { colourDiffs3d, render3d } from './colour-3d.ts';
import type { GpuProbe } from './gpu-probe.ts';
import { probeForSuite } from './probe-suite.ts';

const W = 96;
const H = 72;
const MIN_AGREEMENT = 0.995;
/** The ray parameters of two agreeing hits differ by at most this fraction (float32 march). */
const T_TOLERANCE = 0.02;

let gpu: GpuProbe;
const rows = probeForSuite(W, H, '3D GPU vs CPU parity', (g) => {
  gpu = g;
});

const gpuProbe = (scene: Scene3d, bake = false) => render3d(gpu, scene, { variant: 'probe', bake });

/** (hit, seed) equal, and the depth unless `anyDepth`. */
const same = (a: Float32Array, b: Float32Array, i: number, anyDepth = false) =>
  a[i] === b[i] && (a[i] === 0 || ((anyDepth || a[i + 2] === b[i + 2]) && a[i + 3] === b[i + 3]));

/**
 * Scenes whose surface is a limit set (the sphairahedra, inside their parameter space or, with
 * bridges and tunnels, outside it; the tiling after 20 inversions, already the terrain's fine
 * grain; the pseudo-Kleinian's clusters, a third of its pixels): the depth of the hit tile changes from one quarter pixel to
 * the next almost everywhere, so no pixel would be robust in depth; they are compared on hit, seed
 * and t only.
 */
const LIMIT_SET_SURFACES =
  /quasi-sphere|fractal-terrain|tiling-step-20|parameter-space|bridges|tunnels|pseudo-kleinian/;

function compare(scene: Scene3d, gpuData: Float32Array, anyDepth = false) {
  const centre = probeScene3d(scene, W, H);
  const shifted = (
    [
      [0.25, 0.5],
      [0.75, 0.5],
      [0.5, 0.25],
      [0.5, 0.75],
    ] as const
  ).map((j) => probeScene3d(scene, W, H, j));
  let robust = 0;
  let agree = 0;
  let hits = 0;
  for (let i = 0; i < W * H * 4; i += 4) {
    if (!shifted.every((s) => same(s, centre, i, anyDepth))) continue;
    robust++;
    if (centre[i] === 1) hits++;
    const t = centre[i + 1]!;
    const ok =
      same(centre, gpuData, i, anyDepth) &&
      (centre[i] === 0 || Math.abs(gpuData[i + 1]! - t) <= T_TOLERANCE * t);
    if (ok) agree++;
  }
  return { robust, agree, hits, agreement: agree / robust };
}

const examples = exampleScenes3d();
/**
 * The examples with their own geometry: the first of those that differ only in colouring (the
 * Figs. 33–34 quasi-spheres are Fig. 26's), since hit, depth and seed do not depend on colour.
 */
function distinctGeometry(scenes: Record<string, Scene3d>): Record<string, Scene3d> {
  const seen = new Set<string>();
  return Object.fromEntries(
    Object.entries(scenes).filter(([, s]) => {
      const { elements, seeds, camera, maxIterations, marchSteps, deScale } = s;
      const key = JSON.stringify({ elements, seeds, camera, maxIterations, marchSteps, deScale });
      return !seen.has(key) && seen.add(key);
    }),
  );
}

describe('3D sphere tracer: GPU = CPU (SwiftShader)', () => {
  const scenes: Record<string, Scene3d> = {
    fig11: FIG11,
    'mobius-box': MOBIUS_BOX,
    planes: PLANES,
    'pseudo-kleinian': PSEUDO_KLEINIAN,
    // Every 3D example, the sphairahedra (Figs. 26, 28, the cake: overlapping mirrors, the
    // mirrored covers of docs/math-3d.md §8) and the unbounded plane orbits (Figs. 17–18) included.
    ...distinctGeometry(examples),
  };
  // Nothing to trace: a limit set without seeds is dots painted over the picture on the CPU
  // (tests/shader-gen/space/limit-dfs-3d.test.ts, tests/cli/render-limit-set.test.ts).
  for (const [name, s] of Object.entries(scenes)) if (s.seeds.length === 0 && !s.volume) delete scenes[name];
  for (const [name, scene] of Object.entries(scenes)) {
    it(`${name}: hit/miss, depth and seed agree on ≥ 99.5 % of robust pixels`, async () => {
      const image = await gpuProbe(scene);
      const stats = compare(scene, image.data, LIMIT_SET_SURFACES.test(name));
      rows[name] = {
        agreement: `${(100 * stats.agreement).toFixed(2)} %`,
        robust: stats.robust,
        'robust hits': stats.hits,
        'GPU ms': Math.round(image.ms),
      };
      expect(stats.robust).toBeGreaterThan(0.8 * W * H);
      expect(stats.hits).toBeGreaterThan(0.01 * W * H); // the picture is not empty
      expect(stats.agreement).toBeGreaterThanOrEqual(MIN_AGREEMENT);
    }, 300_000); // the sphairahedra take minutes of CPU probes on a busy machine
  }

  it('shades like the CPU: normals, every colouring, light, occlusion and shadow (colour variant)', async () => {
    // Fig. 11: the depth wheel; the cosine palette; by final point, and the same scene by surface
    // point, by distance from the origin (a named palette) and by argument (the colour wheel).
    const fig34 = examples['orbit-colour-by-final-point']!;
    const { a, b, c, d } = PALETTES.dusk!;
    const scenes: Record<string, Scene3d> = {
      fig11: FIG11,
      fig24: examples['fig24-orbit-of-a-cube']!,
      cosine: examples['orbit-cosine-palette']!,
      fig34: fig34,
      'fig34 by surface': { ...fig34, coloring: { mode: 'surface', scale: 0.45 } },
      'by distance': {
        ...fig34,
        coloring: { mode: 'distance', wheel: false, a, b, c, d, frequency: 2.5, offset: 0.1 },
      },
      'by argument': {
        ...fig34,
        coloring: { mode: 'argument', wheel: true, a, b, c, d, frequency: 2, offset: 0.3 },
      },
      // A quasi-sphere (overlapping mirrors, deep tiny tiles) by the hit point's distance.
      'fig34 quasi-sphere by distance': examples['fig34-quasi-sphere-by-distance']!,
      // A colour function of the hit point and the depth (docs/formula.md "In 3D").
      'by formula': {
        ...fig34,
        coloring: {
          mode: 'formula',
          wheel: false,
          a,
          b,
          c,
          d,
          frequency: 1,
          offset: 0.2,
          formula: 'n / 5 + 0.8 * z + 0.3 * sin(4 * atan2(y, x))',
        },
      },
    };
    expect(new Set(Object.values(scenes).map((s) => s.coloring.mode))).toEqual(
      new Set(['depth-wheel', 'cosine', 'final-point', 'surface', 'distance', 'argument', 'formula']),
    );
    const results: { name: string; pixels: number; median: number; p95: number; byPoint: boolean }[] = [];
    for (const [name, scene] of Object.entries(scenes)) {
      const { pixels, median, p95 } = await colourDiffs3d(gpu, scene, 2, (plan, r, gpuAlpha) =>
        r.hit.hit && gpuAlpha === 1 ? shadeHit(plan, r.o, r.d, r.angle, r.hit) : null,
      );
      rows[`${name} colour`] = { pixels, median: median.toFixed(5), p95: p95.toFixed(5) };
      results.push({
        name,
        pixels,
        median,
        p95,
        byPoint: scene.coloring.mode === 'final-point',
      });
    }
    for (const r of results) {
      // Measured at 64×48: median ≤ 0.0001, 95th percentile ≤ 0.003 (linear RGB); a few pixels
      // whose shadow ray grazes an orbit sphere differ more. By final point the colour changes at
      // each copy's own scale, so in copies a few pixels wide a float32 shift of the hit moves it
      // more: measured at 96×72, median 0.0002, 95th percentile 0.034 with the old per-step fold,
      // 0.051 with the end-of-walk bound, whose longer march steps land anywhere in the quarter-pixel
      // hit band (GPU and CPU then stop a float32 shift apart on a different spot of a tiny copy).
      expect(r.pixels, r.name).toBeGreaterThan(100);
      expect(r.median, r.name).toBeLessThan(0.002);
      expect(r.p95, r.name).toBeLessThan(r.byPoint ? 0.08 : 0.02);
    }
  }, 300_000);

  it('the baked program draws what the uniform program draws (Fig. 11)', async () => {
    const a = await gpuProbe(FIG11);
    const b = await gpuProbe(FIG11, true);
    let differ = 0;
    for (let i = 0; i < W * H * 4; i += 4) if (!same(a.data, b.data, i)) differ++;
    expect(differ / (W * H)).toBeLessThan(0.005);
  }, 120_000);

  for (const { example, source } of HAND_WRITTEN_3D) {
    it(`the hand-written bench tracer draws what the generated program draws (${example})`, async () => {
      const scene = examples[example]!;
      const generated = await gpuProbe(scene, true);
      const index = await gpu.program(compile3d(scene).vertexSource, source);
      const image = await gpu.render(index, cameraUniforms(scene.camera), { center: [0, 0], scale: 1 });
      expect(image.data.filter((_, i) => i % 4 === 0 && image.data[i] === 1).length).toBeGreaterThan(
        0.05 * W * H,
      );
      // The bench's condition: the two agree on hit or miss for more than 99 % of the pixels.
      expect(hitMissDiffer(generated.data, image.data)).toBeLessThan(0.01);
    }, 120_000);
  }

  it('a moved seed re-renders from new uniform values without a new program', async () => {
    const moved: Scene3d = {
      ...FIG11,
      seeds: [
        { ...FIG11.seeds[0]!, sphere: { center: [0, 0, 0], radius: 0.45 } } as Scene3d['seeds'][number],
      ],
    };
    const a = compile3d(FIG11, { variant: 'probe' });
    const b = compile3d(moved, { variant: 'probe' });
    expect(b.source).toBe(a.source);
    const before = await gpu.compileCount();
    const index = await gpu.program(a.vertexSource, a.source);
    const compiled = await gpu.compileCount();
    const image = await gpu.render(index, [...b.uniforms, ...cameraUniforms(moved.camera)], {
      center: [0, 0],
      scale: 1,
    });
    expect(await gpu.compileCount()).toBe(compiled);
    expect(compiled - before).toBe(2);
    const stats = compare(moved, image.data);
    expect(stats.agreement).toBeGreaterThanOrEqual(MIN_AGREEMENT);
  }, 120_000);
});
