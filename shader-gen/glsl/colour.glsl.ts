/**
 * GLSL twin of shader-gen/colour.ts, function by function (same names, same formulas). The fixed
 * functions are constants; depthColour and shade read the tile's values (uniforms or literals)
 * and are specialised to its colouring mode and to edges on/off.
 *
 * Speed: the tile's colours are constants of the scene, so they are decoded to linear light here,
 * in TypeScript (srgb.ts), and reach the shader already linear — as literals when baked, as
 * uniforms holding the linear value otherwise. Only colours computed per pixel (HSV and cosine
 * palettes) are decoded on the GPU. Where nothing is blended (one sample, no edges, glow, fade or
 * picture: see `shadesWithoutBlending`) shade can work in sRGB throughout and the output needs no
 * encoding at all (`ColourSpace`).
 */
import { pictureKey } from '../../nodes/core/live-source.ts';
import type { Coloring, TileSpec } from '../../nodes/core/scene.ts';
import type { Color } from '../../nodes/core/values.ts';
import type { DepthColoring, MeasureColoring } from '../colour.ts';
import { rotationPair } from '../placement.ts';
import { toLinear } from '../srgb.ts';
import { floatLiteral } from './literal.ts';
import { placeUvGlsl } from './placement.glsl.ts';
import { type GlslFunction, glslFunction } from './snippet.ts';
import type { SceneValues } from './values.ts';

/**
 * The space shade's colours are in: `linear` (what accumulation and blending need) or `srgb` (the
 * output as is, when a single sample is shaded without blending).
 */
export type ColourSpace = 'linear' | 'srgb';

/**
 * A tile colour (sRGB, as documents store it) as a shader value in `space`: decoded to linear
 * light at generation time (srgb.ts toLinear), never per pixel.
 */
export function colourValue(v: SceneValues, name: string, c: Color, space: ColourSpace): string {
  return v.vec(name, space === 'linear' ? toLinear(c) : c);
}

/**
 * Whether every colour shade returns is one of the tile's colours or a depth colour as it is, with
 * nothing mixed, faded or sampled: then sRGB in is sRGB out and one sample needs no conversion.
 */
export function shadesWithoutBlending(tile: TileSpec): boolean {
  const mode = tile.coloring.mode;
  const seeds = tile.seeds ?? [];
  if (seeds.length > 0 && (tile.seedFade || seeds.some((s) => s.kind === 'image'))) return false;
  if (tile.seedsOnly) return true;
  return tile.edgeWidth <= 0 && mode !== 'limit-set' && mode !== 'image' && mode !== 'measure';
}

export const srgbToLinearGlsl = glslFunction(
  'srgbToLinear',
  `
float srgbToLinear(float c) {
  return c <= 0.04045 ? c / 12.92 : pow((c + 0.055) / 1.055, 2.4);
}`,
);

export const linearToSrgbGlsl = glslFunction(
  'linearToSrgb',
  `
float linearToSrgb(float c) {
  return c <= 0.0031308 ? 12.92 * c : 1.055 * pow(c, 1.0 / 2.4) - 0.055;
}`,
);

export const toLinearGlsl = glslFunction(
  'toLinear',
  `
vec3 toLinear(vec3 c) {
  return vec3(srgbToLinear(c.r), srgbToLinear(c.g), srgbToLinear(c.b));
}`,
  [srgbToLinearGlsl],
);

/** The encoding direction for a whole colour (the Shadertoy version outputs sRGB itself). */
export const toSrgbGlsl = glslFunction(
  'toSrgb',
  `
vec3 toSrgb(vec3 c) {
  return vec3(linearToSrgb(c.r), linearToSrgb(c.g), linearToSrgb(c.b));
}`,
  [linearToSrgbGlsl],
);

export const hsvToRgbGlsl = glslFunction(
  'hsvToRgb',
  `
float hsvChannel(float h, float s, float v, float k) {
  return v * (1.0 - s * (1.0 - clamp(abs(fract(h + k) * 6.0 - 3.0) - 1.0, 0.0, 1.0)));
}
vec3 hsvToRgb(float h, float s, float v) {
  return vec3(hsvChannel(h, s, v, 0.0), hsvChannel(h, s, v, ${floatLiteral(2 / 3)}), hsvChannel(h, s, v, ${floatLiteral(1 / 3)}));
}`,
);

export const cosinePaletteGlsl = glslFunction(
  'cosinePalette',
  `
vec3 cosinePalette(vec3 a, vec3 b, vec3 c, vec3 d, float t) {
  return clamp(a + b * cos(${floatLiteral(2 * Math.PI)} * (c * t + d)), 0.0, 1.0);
}`,
);

/**
 * `vec3 depthColour(int depth)`: the sRGB colour of an escaped point, for the palette modes (a
 * parity tile's two colours are constants, see finalColourGlsl).
 */
export function depthColourGlsl(
  coloring: Exclude<DepthColoring, { mode: 'parity' }>,
  v: SceneValues,
): GlslFunction {
  const head = 'vec3 depthColour(int depth) {';
  switch (coloring.mode) {
    case 'depth-hsv': {
      const hsv = v.vec('u_hsv', [coloring.hueOffset, coloring.hueStep, coloring.saturation, coloring.value]);
      return glslFunction(
        'depthColour',
        `${head}\n  vec4 hsv = ${hsv};\n  return hsvToRgb(hsv.x + hsv.y * float(depth), hsv.z, hsv.w);\n}`,
        [hsvToRgbGlsl],
      );
    }
    case 'cosine': {
      const [a, b, c, d] = (['a', 'b', 'c', 'd'] as const).map((k) =>
        v.vec(`u_palette${k.toUpperCase()}`, coloring[k]),
      );
      const step = v.float('u_paletteStep', coloring.step);
      return glslFunction(
        'depthColour',
        `${head}\n  return cosinePalette(${a}, ${b}, ${c}, ${d}, float(depth) * ${step});\n}`,
        [cosinePaletteGlsl],
      );
    }
  }
}

/**
 * `vec3 finalColour(int depth, vec2 p)`: colour of an escaped point in `space` (colour.ts
 * finalColour): the picture's texel at p in image mode (linear only; u_picture = (c.x, c.y, w, h),
 * u_pictureRot = (cos θ, sin θ)), the parity colours (constants), else the palette's depth colour.
 */
export function finalColourGlsl(
  coloring: Exclude<Coloring, { mode: 'limit-set' | 'measure' }>,
  v: SceneValues,
  space: ColourSpace,
): GlslFunction {
  const head = 'vec3 finalColour(int depth, vec2 p) {';
  if (coloring.mode === 'parity') {
    const even = colourValue(v, 'u_even', coloring.even, space);
    const odd = colourValue(v, 'u_odd', coloring.odd, space);
    return glslFunction('finalColour', `${head}\n  return depth % 2 == 0 ? ${even} : ${odd};\n}`);
  }
  if (coloring.mode !== 'image') {
    const depth = depthColourGlsl(coloring, v);
    if (space === 'srgb')
      return glslFunction('finalColour', `${head}\n  return depthColour(depth);\n}`, [depth]);
    return glslFunction('finalColour', `${head}\n  return toLinear(depthColour(depth));\n}`, [
      toLinearGlsl,
      depth,
    ]);
  }
  if (space === 'srgb') throw new Error('a picture is sampled in linear light (shadesWithoutBlending)');
  const { image, center, size, rotation } = coloring;
  const rect = v.vec('u_picture', [center[0], center[1], (size * image.width) / image.height, size]);
  const rot = v.vec('u_pictureRot', rotationPair(rotation));
  const sampler = v.picture(pictureKey(image));
  return glslFunction(
    'finalColour',
    `${head}\n  return textureLod(${sampler}, placeUv(${rect}, ${rot}, p), 0.0).rgb;\n}`,
    [placeUvGlsl],
  );
}

/**
 * `vec3 measureColour(float m)`: colour.ts measureColour, the cosine palette of offset + scale·m,
 * decoded to linear light (the palette is computed per pixel).
 */
export function measureColourGlsl(coloring: MeasureColoring, v: SceneValues): GlslFunction {
  const [a, b, c, d] = (['a', 'b', 'c', 'd'] as const).map((k) =>
    v.vec(`u_palette${k.toUpperCase()}`, coloring[k]),
  );
  const scale = v.float('u_measureScale', coloring.scale);
  const offset = v.float('u_measureOffset', coloring.offset);
  return glslFunction(
    'measureColour',
    `vec3 measureColour(float m) {\n  return toLinear(cosinePalette(${a}, ${b}, ${c}, ${d}, ${offset} + ${scale} * m));\n}`,
    [toLinearGlsl, cosinePaletteGlsl],
  );
}

/**
 * `vec3 shade(bool clipped, bool escaped, int depth, float edgePixels, vec2 p, float limitPixels,
 * int seed[, float measure])`: colour of one sample in `space` (linear unless shadesWithoutBlending), in colour.ts
 * shade's order (clip, seed, seeds only, limit-set mode, limit, inner circle, fill, mode colour,
 * edges); each option is emitted only when the tile uses it (the `measure` argument too: measure
 * mode only). Edges have a 1-pixel antialiased
 * falloff, t = clamp(edgePixels − width/2 + 0.5, 0, 1).
 */
export function shadeGlsl(
  tile: TileSpec,
  v: SceneValues,
  seedColour: GlslFunction | null,
  space: ColourSpace = 'linear',
): GlslFunction {
  if (space === 'srgb' && !shadesWithoutBlending(tile))
    throw new Error('this tile blends: shade it in linear light');
  const background = colourValue(v, 'u_background', tile.background, space);
  const limit = colourValue(v, 'u_limitColor', tile.limitColor, space);
  const deps: GlslFunction[] = [];
  const coloring = tile.coloring;
  const measured = coloring.mode === 'measure' ? coloring : null;
  const lines = [
    `vec3 shade(bool clipped, bool escaped, int depth, float edgePixels, vec2 p, float limitPixels, int seed${measured ? ', float measure' : ''}) {`,
    `  if (clipped) return ${background};`,
  ];
  if (seedColour) {
    if (tile.seedFade) {
      const fade = v.float('u_seedFade', tile.seedFade);
      lines.push(`  if (seed >= 0) return seedColour(seed, p) * max(0.0, 1.0 - ${fade} * float(depth));`);
    } else lines.push('  if (seed >= 0) return seedColour(seed, p);');
    deps.push(seedColour);
  }
  if (tile.seedsOnly) lines.push(`  return ${background};`, '}');
  else if (tile.coloring.mode === 'limit-set') {
    lines.push(`  if (!escaped) return ${limit};`, '  float line = clamp(1.0 - limitPixels, 0.0, 1.0);');
    if (tile.coloring.glow > 0) {
      const glow = v.float('u_glow', tile.coloring.glow);
      lines.push(`  float glow = exp(-limitPixels / ${glow});`);
    } else lines.push('  float glow = 0.0;');
    lines.push(`  vec3 bg = ${background};`, `  return bg + (${limit} - bg) * max(line, glow);`, '}');
  } else {
    lines.push(`  if (!escaped) return ${limit};`);
    if (tile.inner) {
      const inner = v.vec('u_inner', [tile.inner.c[0], tile.inner.c[1], tile.inner.r]);
      lines.push(
        `  vec3 inner = ${inner};`,
        '  if ((p.x - inner.x) * (p.x - inner.x) + (p.y - inner.y) * (p.y - inner.y) >= inner.z * inner.z)',
        `    return ${background};`,
      );
    }
    let colour = 'finalColour(depth, p)';
    if (coloring.mode === 'measure') {
      deps.push(measureColourGlsl(coloring, v));
      colour = 'measureColour(measure)';
    } else if (coloring.mode !== 'limit-set') deps.push(finalColourGlsl(coloring, v, space));
    if (tile.fill) {
      const fill = colourValue(v, 'u_fill', tile.fill, space);
      lines.push(`  vec3 base = depth == 0 ? ${fill} : ${colour};`);
    } else lines.push(`  vec3 base = ${colour};`);
    if (tile.edgeWidth > 0) {
      const width = v.float('u_edgeWidth', tile.edgeWidth);
      const colour = colourValue(v, 'u_edgeColor', tile.edgeColor, space);
      lines.push(
        `  float t = clamp(edgePixels - ${width} / 2.0 + 0.5, 0.0, 1.0);`,
        `  vec3 edge = ${colour};`,
        '  return edge + (base - edge) * t;',
      );
    } else lines.push('  return base;');
    lines.push('}');
  }
  return glslFunction('shade', lines.join('\n'), deps);
}
