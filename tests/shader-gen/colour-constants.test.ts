/**
 * Colour constants in the generated shader (glsl/colour.glsl.ts): the tile's colours reach the GPU
 * already decoded to linear light (literals when baked, uniforms otherwise), so no shader converts
 * a constant per pixel; and a single-sample Shadertoy image of a tile that blends nothing is
 * shaded in sRGB with no conversion at all. The pixels themselves are checked on the GPU by
 * tests/parity (colour parity and the one-sample Shadertoy case).
 */
import { describe, expect, it } from 'vitest';
import type { Scene } from '../../nodes/core/scene.ts';
import { compile, shadertoySource } from '../../shader-gen/compile.ts';
import { shadesWithoutBlending } from '../../shader-gen/glsl/colour.glsl.ts';
import { floatLiteral } from '../../shader-gen/glsl/literal.ts';
import { toLinear } from '../../shader-gen/srgb.ts';
import { HAND_MADE_SCENES } from './support/scenes.ts';

const PARITY = HAND_MADE_SCENES['triangle-333-parity-clip'];

describe('tile colours are folded to linear light at generation time', () => {
  it('baked: a parity tile has linear literals and no conversion code', () => {
    const { source } = compile(PARITY, { baked: true });
    expect(source).not.toMatch(/toLinear|srgbToLinear|pow\(/);
    const bg = toLinear(PARITY.tile.background);
    expect(source).toContain(`if (clipped) return vec3(${bg.map(floatLiteral).join(', ')});`);
  });

  it('uniforms: each colour uniform holds the linear value, and the shader does not decode it', () => {
    const { source, uniforms } = compile(PARITY);
    expect(source).not.toMatch(/toLinear|pow\(/);
    const value = (name: string) => uniforms.find((u) => u.name === name)?.value;
    const coloring = PARITY.tile.coloring as Extract<Scene['tile']['coloring'], { mode: 'parity' }>;
    expect(value('u_background')).toEqual(toLinear(PARITY.tile.background));
    expect(value('u_limitColor')).toEqual(toLinear(PARITY.tile.limitColor));
    expect(value('u_even')).toEqual(toLinear(coloring.even));
    expect(value('u_odd')).toEqual(toLinear(coloring.odd));
  });

  it('palettes computed per pixel are still decoded on the GPU (and only they)', () => {
    const { source } = compile(HAND_MADE_SCENES['rose-cosine'], { baked: true });
    expect(source).toContain('return toLinear(depthColour(depth));');
    expect(source.match(/toLinear\(/g)?.length).toBe(2); // its definition and that one call
  });
});

describe('one sample, nothing blended: no conversion at all', () => {
  it('knows which tiles blend', () => {
    const blends = Object.entries(HAND_MADE_SCENES)
      .filter(([, s]) => !shadesWithoutBlending(s.tile))
      .map(([name]) => name);
    expect(blends.sort()).toEqual(
      [
        'every-kind-cosine-edges-clip',
        'loxodromic-parity-edges',
        'matrix-hsv-edges-clip',
        'schottky-cosine-edges',
        'schottky-limit-set',
        'schottky-limit-set-glow',
        'schottky-picture-fill',
        'schottky-seeds-fill-edges',
        'schottky-seeds-only', // seeds fading with depth
        'spherical-wedge-parity-edges',
        'strips-hsv-edges',
        'triangle-333-picture',
        // Measure colourings are shaded in linear light (colour.glsl.ts measureColour).
        'matrix-escape-speed',
        'rose-final-radius',
        'schottky-argument',
        'schottky-colour-formula',
        'schottky-edge-distance',
        'schottky-orbit-trap-seeds',
        'strips-final-y',
        'triangle-333-final-x-edges',
        'triangle-333-orbit-trap',
        'maskit-2i-cosine-edges',
        'maskit-cusp-limit-set',
        'maskit-slice-edges',
        'maskit-slice-limit-set',
      ].sort(),
    );
  });

  it('the single-sample Shadertoy image of a parity tile writes its sRGB colours as they are', () => {
    const src = shadertoySource({ ...PARITY, samples: 1 });
    expect(src).not.toMatch(/toLinear|toSrgb|pow\(|sampleOffset|for \(int k/);
    const bg = PARITY.tile.background;
    expect(src).toContain(`if (clipped) return vec3(${bg.map(floatLiteral).join(', ')});`);
  });

  it('a palette tile at one sample keeps its sRGB depth colour undecoded', () => {
    const src = shadertoySource({ ...HAND_MADE_SCENES['rose-cosine'], samples: 1 });
    expect(src).toContain('return depthColour(depth);');
    expect(src).not.toMatch(/toLinear|toSrgb/);
  });

  it('a tile that blends (edges) is shaded in linear light and encoded once', () => {
    const src = shadertoySource({ ...HAND_MADE_SCENES['schottky-cosine-edges'], samples: 1 });
    expect(src).toContain('fragColor = vec4(toSrgb(shadeSample(');
    expect(src).toContain('toLinear(depthColour(depth))');
  });
});
