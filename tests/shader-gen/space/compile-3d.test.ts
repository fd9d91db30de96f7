/**
 * The 3D GLSL generator (shader-gen/space/compile-3d.ts): every program it writes — uniform and
 * baked, colour and probe, every 3D example, the hand-built scenes, every colouring mode, the
 * Shadertoy version, and the hand-written bench tracers — pass glslangValidator and the WebGL identifier rules; the source depends
 * only on the scene's structure, so value edits re-use the program; baking leaves no scene uniform.
 */
import { describe, expect, it } from 'vitest';
import { LIMITS } from '../../../nodes/core/limits.ts';
import type { Coloring3d, Scene3d } from '../../../nodes/core/scene-3d.ts';
import { uniformRows } from '../../../shader-gen/glsl/values.ts';
import {
  type Compile3dOptions,
  cameraUniforms,
  compile3d,
  FRAME_UNIFORMS_3D,
} from '../../../shader-gen/space/compile-3d.ts';
import { HAND_WRITTEN_3D } from '../../bench/hand-written/trace3d.ts';
import { itPassesGlslang } from '../support/glslang.ts';
import { shaders3d } from './glslang-3d.ts';
import { exampleScenes3d, FIG11, LONE_SPHERE, MIRROR_FIG11, MOBIUS_BOX, PLANES } from './scenes-3d.ts';

const PALETTE = { a: [0.5, 0.5, 0.5], b: [0.5, 0.5, 0.5], c: [1, 1, 1], d: [0, 0.33, 0.67] } as const;

const COLORINGS: Record<string, Coloring3d> = {
  'depth-wheel': { mode: 'depth-wheel', step: 0.1 },
  cosine: {
    mode: 'cosine',
    a: [0.5, 0.5, 0.5],
    b: [0.5, 0.5, 0.5],
    c: [1, 1, 1],
    d: [0, 0.33, 0.67],
    step: 0.1,
  },
  surface: { mode: 'surface', scale: 2 },
  'final-point': { mode: 'final-point', scale: 1.5 },
  distance: { ...PALETTE, mode: 'distance', wheel: false, frequency: 2, offset: 0.1 },
  argument: { ...PALETTE, mode: 'argument', wheel: true, frequency: 3, offset: 0 },
  formula: {
    ...PALETTE,
    mode: 'formula',
    wheel: false,
    frequency: 1,
    offset: 0,
    formula: 'n / 4 + pow(x, 2) - y % 0.5 + round(z)',
  },
};

const SCENES: Record<string, Scene3d> = {
  ...exampleScenes3d(),
  fig11: FIG11,
  lone: LONE_SPHERE,
  'mobius-box': MOBIUS_BOX,
  planes: PLANES,
  'no-seeds': { ...FIG11, seeds: [] },
  'no-elements': { ...LONE_SPHERE, elements: [] },
  // docs/math-3d.md "Mirror material": the reflection loop, under the sky and the flat background.
  mirror: MIRROR_FIG11,
  'mirror-flat': { ...MIRROR_FIG11, environment: { mode: 'flat' } },
  ...Object.fromEntries(
    Object.entries(COLORINGS).map(([k, coloring]) => [`coloring-${k}`, { ...MOBIUS_BOX, coloring }]),
  ),
};

const VARIANTS: Record<string, Compile3dOptions> = {
  color: {},
  'color-baked': { bake: true },
  probe: { variant: 'probe' },
  'probe-baked': { variant: 'probe', bake: true },
};

describe('compile3d', () => {
  itPassesGlslang(shaders3d(SCENES, VARIANTS, HAND_WRITTEN_3D));

  it('covers every 3D example', () => {
    expect(Object.keys(exampleScenes3d()).length).toBeGreaterThanOrEqual(8);
  });

  it('writes the same source for new values (moved spheres, colours, lighting, budgets)', () => {
    const moved: Scene3d = {
      ...FIG11,
      elements: FIG11.elements.map((e) =>
        e.kind === 'sphere-inversion' ? { ...e, sphere: { ...e.sphere, radius: e.sphere.radius * 0.9 } } : e,
      ),
      seeds: [{ ...FIG11.seeds[0]!, color: [0.1, 0.9, 0.3] }],
      lighting: { ...FIG11.lighting, shadow: 0, diffuse: 0.3 },
      maxIterations: 77,
      marchSteps: 321,
      deScale: 0.6,
      background: [1, 1, 1],
    };
    const a = compile3d(FIG11);
    const b = compile3d(moved);
    expect(b.source).toBe(a.source);
    expect(b.uniforms).not.toEqual(a.uniforms);
  });

  it('declares the frame uniforms, bakes every scene value when asked, and fits the uniform budget', () => {
    for (const [name, scene] of Object.entries(SCENES)) {
      const c = compile3d(scene);
      for (const u of FRAME_UNIFORMS_3D) expect(c.source, name).toContain(`uniform ${u.type} ${u.name};`);
      const rows = c.uniforms.reduce((n: number, u) => n + uniformRows(u), FRAME_UNIFORMS_3D.length);
      expect(rows, name).toBeLessThanOrEqual(LIMITS.maxUniformVectors);
      expect(
        c.uniforms.every((u) => u.value.every(Number.isFinite)),
        name,
      ).toBe(true);
      const baked = compile3d(scene, { bake: true });
      expect(baked.uniforms, name).toEqual([]);
      expect(baked.source, name).not.toContain('u_el');
    }
    expect(cameraUniforms(FIG11.camera).map((u) => u.name)).toEqual([
      'u_cameraPosition',
      'u_cameraTarget',
      'u_cameraFov',
    ]);
  });

  it('keeps the source when a reflectivity, the reflections or the sky colours change (uniforms)', () => {
    const dragged: Scene3d = {
      ...MIRROR_FIG11,
      seeds: MIRROR_FIG11.seeds.map((s, k) => (k === 0 ? { ...s, reflectivity: 0.3 } : s)),
      reflections: 4,
      environment: { mode: 'sky', horizon: [1, 0, 0], ground: [0, 1, 0] },
    };
    const a = compile3d(MIRROR_FIG11);
    const b = compile3d(dragged);
    expect(b.source).toBe(a.source);
    expect(b.uniforms).not.toEqual(a.uniforms);
    expect(a.uniforms.map((u) => u.name)).toEqual(
      expect.arrayContaining(['u_reflections', 'u_seedReflectivity0', 'u_horizon', 'u_ground']),
    );
    // A material or the kind of environment is structure: matte scenes carry no reflection loop.
    const matte = { ...MIRROR_FIG11, seeds: MIRROR_FIG11.seeds.map(({ reflectivity: _, ...s }) => s) };
    expect(compile3d(matte).source).not.toContain('seedReflectivity');
    expect(compile3d(matte).source).not.toBe(a.source);
  });

  it('changes the source with the structure (another element kind)', () => {
    expect(compile3d(MOBIUS_BOX).source).not.toBe(compile3d(FIG11).source);
  });
});
