/**
 * The GLSL volume renderer, twin of ../volume-3d.ts line by line (docs/math-3d.md "§11 Volume
 * rendering of the nesting depth"): the pixel's sample offset (the same integer hash, in uint
 * arithmetic mod 2³²), the span in the regions' ball, N samples of walkPlain's depth through the
 * transfer, front-to-back compositing with the early exit. The colour is a function of the depth
 * alone, so it is only recomputed when the depth changes from one sample to the next. Values that users drag (samples, density,
 * depth range, palette, bounds) come through `v` (uniforms, or literals when baked).
 */
import type { Volume3d } from '../../../nodes/core/scene-3d.ts';
import { cosinePaletteGlsl, toLinearGlsl } from '../../glsl/colour.glsl.ts';
import { floatLiteral } from '../../glsl/literal.ts';
import { type GlslFunction, glslFunction } from '../../glsl/snippet.ts';
import type { SceneValues } from '../../glsl/values.ts';
import { EXIT_TRANSMITTANCE, type VolumeBounds } from '../volume-3d.ts';
import { rayIntervalGlsl } from './trace.glsl.ts';

const hashGlsl = glslFunction(
  'hash32',
  `
uint hash32(uint x) {
  x ^= x >> 16u;
  x *= 0x7feb352du;
  x ^= x >> 15u;
  x *= 0x846ca68bu;
  x ^= x >> 16u;
  return x;
}`,
);

/** `float volumeJitter(vec2 pixel)`: ../volume-3d.ts volumeJitter of the pixel's integer coordinates. */
const jitterGlsl = glslFunction(
  'volumeJitter',
  `
float volumeJitter(vec2 pixel) {
  uvec2 q = uvec2(ivec2(floor(pixel)));
  return float(hash32(q.x + hash32(q.y)) >> 8u) / 16777216.0;
}`,
  [hashGlsl],
);

/**
 * `float volumeRay(vec3 o, vec3 d, float jitter, out vec3 rgb)` → (T, τ, samples, 0) and the
 * premultiplied colour: ../volume-3d.ts volumeRay. Needs walkPlain.
 */
export function volumeGlsl(vb: VolumeBounds | null, volume: Volume3d, v: SceneValues): GlslFunction {
  const b = vb?.bounds ?? { center: [0, 0, 0], radius: 1 };
  const bounds = v.vec('u_volumeBounds', [...b.center, b.radius]);
  const mode = v.float('u_volumeBoundsMode', vb?.bounded === false ? 1 : 0);
  const steps = v.int('u_volumeSteps', volume.steps);
  const transfer = v.vec('u_volume', [volume.density, volume.depthFrom, volume.depthTo, volume.growth]);
  const [pa, pb, pc, pd] = (['a', 'b', 'c', 'd'] as const).map((k) =>
    v.vec(`u_volumePalette${k.toUpperCase()}`, volume[k]),
  );
  return glslFunction(
    'volumeRay',
    `
vec4 volumeRay(vec3 o, vec3 d, float jitter, out vec3 rgb) {
  rgb = vec3(0.0);
  vec2 span;
  if (${vb ? '!volumeInterval(o, d, span)' : 'true'}) return vec4(1.0, 0.0, 0.0, 0.0);
  int n = ${steps};
  vec4 tr = ${transfer};
  float dt = (span.y - span.x) / float(n);
  float T = 1.0;
  float tau = 0.0;
  float lastK = -1.0;
  vec3 colour = vec3(0.0);
  for (int i = 0; i < n; ++i) {
    float t = span.x + (float(i) + jitter) * dt;
    vec4 info;
    vec3 fin;
    walkPlain(o + d * t, info, fin);
    if (info.y < tr.y) continue;
    float k = min(info.y, tr.z);
    float u = (k - tr.y + 1.0) / (tr.z - tr.y + 1.0);
    float sigma = tr.x * pow(tr.w, k - tr.y) * dt;
    tau += sigma;
    float alpha = 1.0 - exp(-sigma);
    if (k != lastK) {
      colour = toLinear(cosinePalette(${pa}, ${pb}, ${pc}, ${pd}, u));
      lastK = k;
    }
    rgb += T * alpha * colour;
    T *= 1.0 - alpha;
    if (T < ${floatLiteral(EXIT_TRANSMITTANCE)}) return vec4(T, tau, float(i + 1), 0.0);
  }
  return vec4(T, tau, float(n), 0.0);
}`,
    [rayIntervalGlsl('volumeInterval', bounds, mode), jitterGlsl, toLinearGlsl, cosinePaletteGlsl],
  );
}
