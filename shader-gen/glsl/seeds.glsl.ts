/**
 * GLSL twin of shader-gen/seeds.ts: `int seedAt(vec2 p)` (one straight-line test per seed, in
 * order) and `vec3 seedColour(int seed, vec2 p)`. Data per seed: u_seedN = (c.x, c.y, r, 0) and
 * u_seedColorN for a disk; u_seedN = (c.x, c.y, w, h), u_seedRotN = (cos θ, sin θ) and a sampler
 * for an image rectangle.
 */
import type { SeedSpec } from '../../nodes/core/scene.ts';
import { rotationPair } from '../placement.ts';
import { toLinearGlsl } from './colour.glsl.ts';
import { placeUvGlsl } from './placement.glsl.ts';
import { type GlslFunction, glslFunction } from './snippet.ts';
import type { SceneValues } from './values.ts';

/** Disk seed: |p − c|² < r², written as seeds.ts writes it. */
export const seedDiskInsideGlsl = glslFunction(
  'seedDiskInside',
  `
bool seedDiskInside(vec2 p, vec4 d) {
  return (p.x - d.x) * (p.x - d.x) + (p.y - d.y) * (p.y - d.y) < d.z * d.z;
}`,
);

export interface SeedsGlsl {
  readonly seedAt: GlslFunction;
  readonly seedColour: GlslFunction;
}

export function seedsGlsl(seeds: readonly SeedSpec[], v: SceneValues): SeedsGlsl {
  const at = ['int seedAt(vec2 p) {'];
  const colour = ['vec3 seedColour(int seed, vec2 p) {'];
  seeds.forEach((seed, i) => {
    if (seed.kind === 'disk') {
      const d = v.vec(`u_seed${i}`, [seed.c[0], seed.c[1], seed.r, 0]);
      const c = v.vec(`u_seedColor${i}`, seed.color);
      at.push(`  if (seedDiskInside(p, ${d})) return ${i};`);
      colour.push(`  if (seed == ${i}) return toLinear(${c});`);
    } else {
      const rect = v.vec(`u_seed${i}`, [seed.center[0], seed.center[1], seed.width, seed.height]);
      const rot = v.vec(`u_seedRot${i}`, rotationPair(seed.rotation));
      const sampler = v.picture(seed.image.src);
      at.push(
        '  {',
        `    vec2 uv = placeUv(${rect}, ${rot}, p);`,
        `    if (uv.x > 0.0 && uv.x < 1.0 && uv.y > 0.0 && uv.y < 1.0) return ${i};`,
        '  }',
      );
      colour.push(`  if (seed == ${i}) return textureLod(${sampler}, placeUv(${rect}, ${rot}, p), 0.0).rgb;`);
    }
  });
  at.push('  return -1;', '}');
  colour.push('  return vec3(0.0);', '}');
  return {
    seedAt: glslFunction('seedAt', at.join('\n'), [seedDiskInsideGlsl, placeUvGlsl]),
    seedColour: glslFunction('seedColour', colour.join('\n'), [toLinearGlsl, placeUvGlsl]),
  };
}
