/**
 * The formula GLSL writer: every operator and function of the language written out for one
 * checked tree compiles as GLSL ES 3.00 (glslangValidator), names map to the caller's
 * expressions, constants and numbers become literals, and user text never reaches the source
 * except through the tree. GPU = CPU values are checked by the parity suite's seed-shape scene.
 */
import { describe, expect, it } from 'vitest';
import { checkedFormula } from '../../../nodes/formula/checked.ts';
import { FUNCTIONS } from '../../../nodes/formula/functions.ts';
import { SHAPE_NAMES } from '../../../nodes/formula/names.ts';
import { formulaGlsl } from '../../../shader-gen/glsl/formula.glsl.ts';
import { SHAPE_GLSL_NAMES } from '../../../shader-gen/glsl/seeds.glsl.ts';
import { collectFunctions } from '../../../shader-gen/glsl/snippet.ts';
import { validateShaders } from '../support/glslang.ts';

/** The names as a seed shape's GLSL function has them (k = a, b, c, t; pts = p, q). */
const NAMES = SHAPE_GLSL_NAMES;

/** A number formula using every function once, and every operator. */
const EVERY = [
  'abs(a) + sign(b) + sqrt(c) + exp(t) + log(a + 2) + sin(x) + cos(y) + tan(a)',
  'asin(0.5) + acos(0.5) + atan(a) + atan2(y, x) + floor(a) + ceil(b) + round(c) + fract(t)',
  'radians(90) + degrees(pi) + pow(a, 3) + mod(a, 2) + min(a, b) + max(a, b, c) + clamp(x, 0, 1)',
  'mix(a, b, 0.5) + mix(p, q, t).x + point(a, b).y + length(z) + distance(p, q) + dot(p, q)',
  'rotate(z - p, tau / 5).y + (a < b ? 1 : -1) + (a <= b && !(b == c) || a != t ? +a : -b)',
  'a ** 2 + a % 3 + (z * 2 + p / 2 - q).x + e',
].join(' + ');

function shaderFor(text: string): string {
  const f = checkedFormula(text, SHAPE_NAMES);
  if (!('run' in f)) throw new Error(f.message);
  const g = formulaGlsl(f.tree, NAMES);
  return [
    '#version 300 es',
    'precision highp float;',
    'uniform vec4 k;',
    'uniform vec4 pts;',
    'out vec4 o;',
    ...collectFunctions(g.deps),
    `float shape(vec2 z) { return ${g.expr}; }`,
    'void main() { o = vec4(shape(gl_FragCoord.xy)); }',
  ].join('\n');
}

describe('formulaGlsl', () => {
  it('uses every function of the language in the test formula', () => {
    for (const name of Object.keys(FUNCTIONS)) expect(EVERY, name).toContain(`${name}(`);
  });

  it('writes GLSL that glslang accepts, for every operator and function', () => {
    const results = validateShaders([{ name: 'formula-every', source: shaderFor(EVERY), stage: 'frag' }]);
    expect(results.get('formula-every')).toEqual([]);
  });

  it('maps names, writes numbers and constants as literals, and uses the CPU-exact helpers', () => {
    const f = checkedFormula('round(x) + clamp(a, b, c) + 2 ** y + pi', SHAPE_NAMES);
    if (!('run' in f)) throw new Error(f.message);
    const { expr, deps } = formulaGlsl(f.tree, NAMES);
    expect(expr).toBe(
      '(((floor(z.x + 0.5) + min(max(k.x, k.y), k.z)) + kfPow(2.0, z.y)) + 3.141592653589793)',
    );
    expect(deps.map((d) => d.name)).toEqual(['kfPow']);
  });
});
