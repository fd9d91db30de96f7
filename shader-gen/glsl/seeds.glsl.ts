/**
 * GLSL twin of shader-gen/seeds.ts: `int seedAt(vec2 p)` (one straight-line test per seed, in
 * order) and `vec3 seedColour(int seed, vec2 p)`. Data per seed: u_seedN = (c.x, c.y, r, 0) and
 * u_seedColorN for a disk; u_seedN = (c.x, c.y, w, h), u_seedRotN = (cos θ, sin θ) and a sampler
 * for an image rectangle.
 */
import { pictureKey } from '../../nodes/core/live-source.ts';
import type { SeedSpec } from '../../nodes/core/scene.ts';
import { checkedFormula } from '../../nodes/formula/checked.ts';
import { SHAPE_NAMES } from '../../nodes/formula/names.ts';
import { rotationPair } from '../placement.ts';
import { type ColourSpace, colourValue } from './colour.glsl.ts';
import { formulaGlsl } from './formula.glsl.ts';
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

/**
 * `float seedShape<i>(vec2 z, vec4 k, vec4 pts)`: the shape seed's formula (docs/formula.md "Seed
 * shapes"), negative inside, with a, b, c, t in k and p, q in pts — uniforms, so moving a wired
 * point or number recompiles nothing; only a new formula text does.
 */
/** The shape formula's names in `seedShape<i>(vec2 z, vec4 k, vec4 pts)`. */
export const SHAPE_GLSL_NAMES: Readonly<Record<string, string>> = {
  a: 'k.x',
  b: 'k.y',
  c: 'k.z',
  t: 'k.w',
  p: 'pts.xy',
  q: 'pts.zw',
  z: 'z',
  x: 'z.x',
  y: 'z.y',
};

function seedShapeGlsl(seed: Extract<SeedSpec, { kind: 'shape' }>, i: number): GlslFunction {
  const f = checkedFormula(seed.formula, SHAPE_NAMES);
  // The node refuses a formula that does not check, so a scene never holds one; hold nothing then.
  const body = 'run' in f ? formulaGlsl(f.tree, SHAPE_GLSL_NAMES) : { expr: '1.0', deps: [] };
  const name = `seedShape${i}`;
  return glslFunction(
    name,
    `float ${name}(vec2 z, vec4 k, vec4 pts) {\n  return ${body.expr};\n}`,
    body.deps,
  );
}

/** One argument of seedAt after p: its type and the expression the caller passes (uniform or literal). */
export interface SeedArg {
  readonly type: 'vec2' | 'vec4';
  readonly expr: string;
}

export interface SeedsGlsl {
  /** `int seedAt(vec2 p, a0, a1, …)`: the seeds' data are parameters, see `seedAtArgs`. */
  readonly seedAt: GlslFunction;
  /**
   * What to pass to seedAt after p. Parameters rather than uniforms read inside: runIis calls it
   * every pass and copies the uniforms into locals once, before its loop (a uniform read in the
   * loop costs SwiftShader about 2× the frame, see emitRunIis).
   */
  readonly seedAtArgs: readonly SeedArg[];
  readonly seedColour: GlslFunction;
}

/** `space`: the space seedColour returns (shade's, see colour.glsl.ts ColourSpace). */
export function seedsGlsl(
  seeds: readonly SeedSpec[],
  v: SceneValues,
  space: ColourSpace = 'linear',
): SeedsGlsl {
  const args: SeedArg[] = [];
  /** Adds a seedAt parameter for `expr`; returns the parameter's name. */
  const param = (type: SeedArg['type'], expr: string) => {
    args.push({ type, expr });
    return `a${args.length - 1}`;
  };
  const at: string[] = [];
  const shapes: GlslFunction[] = [];
  const colour = ['vec3 seedColour(int seed, vec2 p) {'];
  seeds.forEach((seed, i) => {
    if (seed.kind === 'disk') {
      const d = v.vec(`u_seed${i}`, [seed.c[0], seed.c[1], seed.r, 0]);
      const c = colourValue(v, `u_seedColor${i}`, seed.color, space);
      at.push(`  if (seedDiskInside(p, ${param('vec4', d)})) return ${i};`);
      colour.push(`  if (seed == ${i}) return ${c};`);
    } else if (seed.kind === 'shape') {
      const shape = seedShapeGlsl(seed, i);
      shapes.push(shape);
      const numbers = v.vec(`u_seed${i}`, seed.numbers);
      const points = v.vec(`u_seedPts${i}`, seed.points);
      const c = colourValue(v, `u_seedColor${i}`, seed.color, space);
      at.push(
        `  if (${shape.name}(p, ${param('vec4', numbers)}, ${param('vec4', points)}) < 0.0) return ${i};`,
      );
      colour.push(`  if (seed == ${i}) return ${c};`);
    } else {
      const rect = v.vec(`u_seed${i}`, [seed.center[0], seed.center[1], seed.width, seed.height]);
      const rot = v.vec(`u_seedRot${i}`, rotationPair(seed.rotation));
      const sampler = v.picture(pictureKey(seed.image));
      at.push(
        '  {',
        `    vec2 uv = placeUv(${param('vec4', rect)}, ${param('vec2', rot)}, p);`,
        `    if (uv.x > 0.0 && uv.x < 1.0 && uv.y > 0.0 && uv.y < 1.0) return ${i};`,
        '  }',
      );
      colour.push(`  if (seed == ${i}) return textureLod(${sampler}, placeUv(${rect}, ${rot}, p), 0.0).rgb;`);
    }
  });
  at.unshift(`int seedAt(${['vec2 p', ...args.map((a, k) => `${a.type} a${k}`)].join(', ')}) {`);
  at.push('  return -1;', '}');
  colour.push('  return vec3(0.0);', '}');
  return {
    seedAt: glslFunction('seedAt', at.join('\n'), [seedDiskInsideGlsl, placeUvGlsl, ...shapes]),
    seedAtArgs: args,
    seedColour: glslFunction('seedColour', colour.join('\n'), [placeUvGlsl]),
  };
}
