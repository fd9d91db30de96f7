/**
 * The GLSL environment and mirror reflections, twins of ../reflect-3d.ts line by line
 * (docs/math-3d.md "Mirror material"): `vec3 environment(vec3 d)` and
 * `vec4 radiance(vec3 o, vec3 d, float angle, float bgAlpha)`, which traces and shades the ray
 * and, off mirror seeds, the reflected rays with the same traceRay (alpha: 1 on a hit, bgAlpha
 * where the primary ray hits nothing).
 * The bounce loop runs to the scene's reflections (a uniform, clamped to MAX_REFLECTIONS):
 * dragging the depth or a reflectivity never recompiles. Without mirror seeds the
 * loop is not emitted (radiance is shadeHit or the environment).
 */
import { MAX_REFLECTIONS } from '../../../nodes/core/scene-3d.ts';
import { floatLiteral, intLiteral } from '../../glsl/literal.ts';
import { type GlslFunction, glslFunction } from '../../glsl/snippet.ts';
import type { SceneValues } from '../../glsl/values.ts';
import { toLinear } from '../../srgb.ts';
import type { TracePlan } from '../plan.ts';
import { hasMirrors, reflectionsOf } from '../reflect-3d.ts';

/** `vec3 environment(vec3 d)`: ../reflect-3d.ts environmentOf. */
function environmentGlsl(plan: TracePlan, v: SceneValues): GlslFunction {
  const { background, environment } = plan.scene;
  const zenith = v.vec('u_background', toLinear(background));
  if (environment?.mode !== 'sky')
    return glslFunction('environment', `\nvec3 environment(vec3 d) {\n  return ${zenith};\n}`);
  const horizon = v.vec('u_horizon', toLinear(environment.horizon));
  const ground = v.vec('u_ground', toLinear(environment.ground));
  return glslFunction(
    'environment',
    `
vec3 environment(vec3 d) {
  if (d.z >= 0.0) return mix(${horizon}, ${zenith}, sqrt(d.z));
  float s = -d.z;
  float c = mod(floor(d.x / s) + floor(d.y / s), 2.0);
  return ${ground} * ((1.0 - 0.5 * sqrt(s)) * (1.0 - 0.5 * c * min(1.0, 4.0 * s)));
}`,
  );
}

/** `float seedReflectivity(float k)`: seed k's reflectivity, 0 for a matte seed. */
function seedReflectivityGlsl(plan: TracePlan, v: SceneValues): GlslFunction {
  const rows = plan.scene.seeds.map((s, k) =>
    s.reflectivity === undefined ? '0.0' : v.float(`u_seedReflectivity${k}`, s.reflectivity),
  );
  const lines = ['float seedReflectivity(float k) {'];
  rows.slice(0, -1).forEach((r, k) => {
    lines.push(`  if (k < ${floatLiteral(k + 0.5)}) return ${r};`);
  });
  lines.push(`  return ${rows.at(-1) ?? '0.0'};`, '}');
  return glslFunction('seedReflectivity', lines.join('\n'));
}

/** `radiance`, over the trace and shade functions (../glsl/trace.glsl.ts). */
export function radianceGlsl(plan: TracePlan, v: SceneValues, trace: GlslFunction, shade: GlslFunction) {
  const environment = environmentGlsl(plan, v);
  const head = 'vec4 radiance(vec3 o, vec3 d, float angle, float bgAlpha) {';
  if (!hasMirrors(plan.scene))
    return glslFunction(
      'radiance',
      `
${head}
  float t;
  vec4 info;
  vec3 fin;
  vec3 n;
  vec3 base;
  if (!traceRay(o, d, angle, 0.0, t, info, fin)) return vec4(environment(d), bgAlpha);
  return vec4(shadeHit(o, d, angle, t, info, fin, n, base), 1.0);
}`,
      [trace, shade, environment],
    );
  const depth = v.int('u_reflections', reflectionsOf(plan.scene));
  return glslFunction(
    'radiance',
    `
${head}
  vec3 colour = vec3(0.0);
  vec3 weight = vec3(1.0);
  // At most MAX_REFLECTIONS bounces; a bound read from the uniform (not a constant) keeps the
  // compiler from unrolling the loop into one copy of the march and shading per bounce.
  int depth = min(${depth}, ${intLiteral(MAX_REFLECTIONS)});
  // One call site of traceRay and of shadeHit (the primary ray is bounce 0): the program stays
  // the size of the matte one.
  float t0 = 0.0;
  float t;
  vec4 info;
  vec3 fin;
  for (int bounce = 0; bounce <= depth; ++bounce) {
    if (!traceRay(o, d, angle, t0, t, info, fin))
      return vec4(colour + weight * environment(d), bounce == 0 ? bgAlpha : 1.0);
    vec3 n;
    vec3 base;
    vec3 matte = shadeHit(o, d, angle, t, info, fin, n, base);
    float r = seedReflectivity(info.z);
    if (bounce >= depth || !(r > 0.0)) return vec4(colour + weight * matte, 1.0);
    vec3 p = o + d * t;
    float eps = hitTolerance(angle, t);
    float m = 1.0 - clamp(-dot(d, n), 0.0, 1.0);
    float F = r + (1.0 - r) * (m * m * m * m * m);
    colour += weight * (1.0 - F) * matte;
    weight *= F * base;
    // The reflected ray continues the path: origin moved back by t, its march starting at t.
    d = normalize(d - 2.0 * dot(d, n) * n);
    o = p + n * (2.0 * eps) - d * t;
    t0 = t;
  }
  return vec4(colour, 1.0);
}`,
    [trace, shade, environment, seedReflectivityGlsl(plan, v)],
  );
}
