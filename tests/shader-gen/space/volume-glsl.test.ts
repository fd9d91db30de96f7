/**
 * The GLSL volume renderer (shader-gen/space/glsl/volume.glsl.ts via compile3d): every volume
 * program — colour, probe and volume probe, uniform and baked, Shadertoy — passes glslangValidator
 * and the WebGL identifier rules; the values users drag (samples, density, growth, depth range,
 * palette, the mirrors) are uniforms, so the source stays the same; a volume probe of a surface
 * scene is refused. The hand-written bench renderer passes glslangValidator too.
 */
import { describe, expect, it } from 'vitest';
import type { Scene3d } from '../../../nodes/core/scene-3d.ts';
import { PALETTES } from '../../../nodes/types/colour.ts';
import { compile3d } from '../../../shader-gen/space/compile-3d.ts';
import { HAND_WRITTEN_VOLUME } from '../../bench/hand-written/trace3d.ts';
import { itPassesGlslang } from '../support/glslang.ts';
import { shaders3d } from './glslang-3d.ts';
import { FIG11, PLANES } from './scenes-3d.ts';
import { NESTED, NO_MIRRORS, ONE_MIRROR, VOLUME } from './volume-scenes.ts';

const SCENES: Record<string, Scene3d> = {
  nested: NESTED,
  'one-mirror': ONE_MIRROR,
  'no-mirrors': NO_MIRRORS,
  // Unbounded regions: the span is the tracer's far one.
  planes: { ...PLANES, volume: VOLUME },
};

/** Every variant, uniform and baked (`name.variant` and `name.variant.baked`). */
const VARIANTS = Object.fromEntries(
  (['color', 'probe', 'volume-probe'] as const).flatMap((variant) =>
    [false, true].map((bake) => [`${variant}${bake ? '.baked' : ''}`, { variant, bake }]),
  ),
);

describe('compile3d, volume mode', () => {
  itPassesGlslang(shaders3d(SCENES, VARIANTS, HAND_WRITTEN_VOLUME));

  it('keeps the source when dragged values change (uniforms), and uploads the new values', () => {
    const dragged: Scene3d = {
      ...NESTED,
      elements: NESTED.elements.map((e) =>
        e.kind === 'sphere-inversion' ? { ...e, sphere: { ...e.sphere, radius: e.sphere.radius * 0.9 } } : e,
      ),
      volume: { steps: 200, density: 2, growth: 1.5, depthFrom: 2, depthTo: 9, ...PALETTES.ember! },
    };
    for (const variant of ['color', 'volume-probe'] as const) {
      const a = compile3d(NESTED, { variant });
      const b = compile3d(dragged, { variant });
      expect(b.source).toBe(a.source);
      const value = (name: string) => b.uniforms.find((u) => u.name === name)?.value;
      expect(value('u_volumeSteps')).toEqual([200]);
      expect(value('u_volume')).toEqual([2, 2, 9, 1.5]);
      expect(value('u_volumePaletteD')).toEqual([...PALETTES.ember!.d]);
    }
  });

  it('draws the volume in the colour program, the surfaces in the surface probe', () => {
    expect(compile3d(NESTED).source).toContain('volumeRay(');
    expect(compile3d(NESTED).source).not.toContain('traceRay(');
    expect(compile3d(NESTED, { variant: 'probe' }).source).toContain('traceRay(');
    expect(compile3d(FIG11).source).not.toContain('volumeRay(');
  });

  it('refuses a volume probe of a surface scene', () => {
    expect(() => compile3d(FIG11, { variant: 'volume-probe' })).toThrow(/volume/);
  });
});
