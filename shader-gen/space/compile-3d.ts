/**
 * Scene3d → one GLSL ES 3.00 sphere-tracing fragment shader (docs/math-3d.md "§8 The tracer's distance bound", docs/math-3d.md "§9 The sphere tracer: march, hit, shading"), the 3D twin of
 * shader-gen/compile.ts. The source depends only on the scene's STRUCTURE — the element kinds in
 * order, the number of seeds, the colouring mode, whether every element is a sphere inversion,
 * which seeds are mirrors and the environment's kind (docs/math-3d.md "Mirror material") —
 * and every value (positions, radii, colours, lighting, iteration and march budgets, bounds)
 * travels as a uniform, so editing a value never recompiles; `bake: true` writes them as literals
 * instead (the faster program once the view is still). The CPU tracer (render-3d.ts) is the
 * reference this shader is tested against (tests/parity/trace3d-parity.test.ts).
 *
 * Frame uniforms, set by the runtime per frame (names fixed; the camera stays a uniform when baked):
 *   vec2  u_resolution      full image size in pixels
 *   vec2  u_pixelOffset     offset of this framebuffer within the full image (tiled export)
 *   vec2  u_jitter          sub-pixel sample offset in [0,1)² (shader-gen/view.ts sampleOffset)
 *   float u_bgAlpha         alpha of background pixels (1; 0 for a transparent export)
 *   vec3  u_cameraPosition  the eye (Camera3d.position)
 *   vec3  u_cameraTarget    the point looked at (Camera3d.target); z is up
 *   float u_cameraFov       vertical field of view in degrees (Camera3d.fovDeg)
 * `cameraUniforms(camera)` gives the last three as UniformEntry values.
 *
 * Output (variant 'color'): linear RGB, alpha 1 on a hit and u_bgAlpha on the background, like
 * the 2D colour variant (the viewport accumulates and encodes to sRGB). Variant 'probe' (RGBA32F):
 * (hit 0/1, t, depth, seed) — what parity compares with render-3d.ts probeScene3d.
 */
import type { Camera3d, Scene3d } from '../../nodes/core/scene-3d.ts';
import { toSrgbGlsl } from '../glsl/colour.glsl.ts';
import { floatLiteral, intLiteral, vecLiteral } from '../glsl/literal.ts';
import { collectFunctions, type GlslFunction } from '../glsl/snippet.ts';
import { SourceBuilder } from '../glsl/source.ts';
import { VERTEX_SOURCE } from '../glsl/template.ts';
import { declaration, SceneValues, type UniformEntry } from '../glsl/values.ts';
import { sampleOffsetGlsl } from '../glsl/view.glsl.ts';
import { toLinear } from '../srgb.ts';
import { cameraRayGlsl } from './camera-3d.ts';
import { radianceGlsl } from './glsl/reflect.glsl.ts';
import { shadeGlsl, traceGlsl } from './glsl/trace.glsl.ts';
import { volumeGlsl } from './glsl/volume.glsl.ts';
import { emitSceneGlobals, emitWalk, placeWalk, walkFunctions } from './glsl/walk.glsl.ts';
import { prepareTrace3d } from './plan.ts';
import { volumeBounds } from './volume-3d.ts';

/** 'volume-probe' (volume-rendered scenes only): (1 − T, τ, samples, 0), render-3d.ts probeVolume3d. */
export type Variant3d = 'color' | 'probe' | 'volume-probe';

export interface Compile3dOptions {
  /** Every scene value inlined as a literal (no scene uniforms; the frame uniforms stay). */
  readonly bake?: boolean;
  readonly variant?: Variant3d;
}

export interface Compiled3d {
  /** The fragment shader; also the program's identity (same text → same program). */
  readonly source: string;
  readonly vertexSource: string;
  /** Scene values to upload (empty when baked); sorted by name. */
  readonly uniforms: UniformEntry[];
}

export const FRAME_UNIFORMS_3D = [
  { name: 'u_resolution', type: 'vec2', doc: 'full image size in pixels' },
  { name: 'u_pixelOffset', type: 'vec2', doc: 'offset of this framebuffer within the full image' },
  { name: 'u_jitter', type: 'vec2', doc: 'sub-pixel sample offset in [0,1)²' },
  { name: 'u_bgAlpha', type: 'float', doc: 'alpha of background pixels' },
  { name: 'u_cameraPosition', type: 'vec3', doc: 'camera position' },
  { name: 'u_cameraTarget', type: 'vec3', doc: 'point the camera looks at (z up)' },
  { name: 'u_cameraFov', type: 'float', doc: 'vertical field of view, degrees' },
] as const;

/** The camera's frame uniforms. */
export const cameraUniforms = (c: Camera3d): UniformEntry[] => [
  { name: 'u_cameraPosition', type: 'vec3', value: [...c.position] },
  { name: 'u_cameraTarget', type: 'vec3', value: [...c.target] },
  { name: 'u_cameraFov', type: 'float', value: [c.fovDeg] },
];

const HEADER = ['precision highp float;', 'precision highp int;'];

/**
 * renderSample's body after the ray for the sphere tracer: the ray's radiance (shaded hit and its
 * reflections, or the environment; glsl/reflect.glsl.ts), or the probe.
 */
const traceSample = (shaded: boolean): string[] => [
  '  float angle = 2.0 * tan(radians(fov) * 0.5) / size.y;',
  ...(shaded
    ? ['  return radiance(camPos, d, angle, bgAlpha);']
    : [
        '  float t;',
        '  vec4 info;',
        '  vec3 fin;',
        '  bool hit = traceRay(camPos, d, angle, 0.0, t, info, fin);',
        '  return vec4(hit ? 1.0 : 0.0, t, info.y, info.z);',
      ]),
];

/**
 * renderSample's body for the volume renderer: the medium over the background, straight RGB and
 * alpha 1 − T + T·bgAlpha (volume-3d.ts overBackground), or the volume probe.
 */
const volumeSample = (variant: Variant3d, background: string | null): string[] => [
  '  vec3 rgb;',
  '  vec4 r = volumeRay(camPos, d, volumeJitter(at), rgb);',
  ...(variant === 'color'
    ? [
        `  vec3 bg = ${background};`,
        '  float a = 1.0 - r.x + r.x * bgAlpha;',
        '  return vec4(a > 0.0 ? (rgb + r.x * bgAlpha * bg) / a : bg, a);',
      ]
    : ['  return vec4(1.0 - r.x, r.y, r.z, 0.0);']),
];

/** The scene's functions after the header, and `vec4 renderSample(vec2 at, vec2 size, float bgAlpha)`. */
function emitScene(
  out: SourceBuilder,
  scene: Scene3d,
  v: SceneValues,
  variant: Variant3d,
  extra: GlslFunction[] = [],
) {
  const plan = prepareTrace3d(scene);
  const placed = placeWalk(plan, v);
  const volume = variant !== 'probe' ? scene.volume : undefined;
  if (variant === 'volume-probe' && !volume) throw new Error('a volume probe needs a volume-rendered scene');
  const trace = volume ? null : traceGlsl(plan, v);
  const march = volume ? volumeGlsl(volumeBounds(plan), volume, v) : null;
  const shade = variant === 'color' && trace ? radianceGlsl(plan, v, trace, shadeGlsl(plan, v)) : null;
  // The volume's medium lies over the flat background colour (volume-3d.ts overBackground).
  const background = variant === 'color' && volume ? v.vec('u_background', toLinear(scene.background)) : null;
  let loadsScene = false;
  const emitFunctions = () => {
    loadsScene = emitSceneGlobals(out, placed);
    for (const code of collectFunctions([...walkFunctions(placed), cameraRayGlsl, ...extra]))
      out.push(code, '');
    if (trace) {
      emitWalk(out, placed, true);
      out.push('');
    }
    if (shade || march) {
      emitWalk(out, placed, false);
      out.push('');
    }
    for (const code of collectFunctions([...(trace ? [trace] : []), ...(shade ? [shade] : [])]))
      out.push(code, '');
    if (march) for (const code of collectFunctions([march])) out.push(code, '');
    out.push(
      'vec4 renderSample(vec2 at, vec2 size, vec3 camPos, vec3 camTarget, float fov, float bgAlpha) {',
      '  vec3 d = cameraRay(camPos, camTarget, fov, size, at);',
      ...(march ? volumeSample(variant, background) : traceSample(shade !== null)),
      '}',
      '',
    );
  };
  return { emitFunctions, loadsScene: () => loadsScene };
}

export function compile3d(scene: Scene3d, options: Compile3dOptions = {}): Compiled3d {
  const variant = options.variant ?? 'color';
  const v = new SceneValues(options.bake ?? false);
  const out = new SourceBuilder();
  // Registers the scene's uniforms in v; the text comes after the header.
  const { emitFunctions, loadsScene } = emitScene(out, scene, v, variant);
  const uniforms = v.entries();
  out.push('#version 300 es', ...HEADER, '', '// Frame uniforms (set by the runtime).');
  for (const u of FRAME_UNIFORMS_3D) out.push(`uniform ${u.type} ${u.name}; // ${u.doc}`);
  if (uniforms.length > 0) out.push('// Scene uniforms (values; changing them needs no recompile).');
  for (const u of uniforms) out.push(declaration(u));
  out.push(
    variant === 'color'
      ? 'out vec4 outColor; // linear RGB; alpha u_bgAlpha on the background'
      : 'out vec4 outProbe; // (hit, t, depth, seed)',
    '',
  );
  emitFunctions();
  out.push(
    'void main() {',
    ...(loadsScene() ? ['  loadScene();'] : []),
    '  vec2 px = floor(gl_FragCoord.xy) + u_pixelOffset;',
    `  ${variant === 'color' ? 'outColor' : 'outProbe'} = renderSample(px + u_jitter, u_resolution, u_cameraPosition, u_cameraTarget, u_cameraFov, u_bgAlpha);`,
    '}',
  );
  return { source: out.toString(), vertexSource: VERTEX_SOURCE, uniforms };
}

/**
 * Shadertoy's `mainImage`: every value and the camera baked, `samples` jittered samples per pixel
 * averaged in linear light and encoded to sRGB.
 */
export function shadertoySource3d(scene: Scene3d): string {
  const count = Math.max(1, Math.round(scene.samples));
  const v = new SceneValues(true);
  const out = new SourceBuilder(false).push(
    '// Kleinflow: a 3D Iterated Inversion System, sphere traced; generated from a node graph. Paste into Shadertoy.',
    '',
  );
  const { emitFunctions, loadsScene } = emitScene(out, scene, v, 'color', [toSrgbGlsl, sampleOffsetGlsl]);
  emitFunctions();
  const { position, target, fovDeg } = scene.camera;
  out.push(
    'void mainImage(out vec4 fragColor, in vec2 fragCoord) {',
    ...(loadsScene() ? ['  loadScene();'] : []),
    '  vec3 sum = vec3(0.0);',
    `  for (int k = 0; k < ${intLiteral(count)}; ++k) {`,
    `    sum += renderSample(floor(fragCoord) + sampleOffset(k), iResolution.xy, ${vecLiteral(position)}, ${vecLiteral(target)}, ${floatLiteral(fovDeg)}, 1.0).rgb;`,
    '  }',
    `  fragColor = vec4(toSrgb(sum / ${floatLiteral(count)}), 1.0);`,
    '}',
  );
  return out.toString();
}
