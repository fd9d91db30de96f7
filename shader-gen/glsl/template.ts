/**
 * Assembles the whole shader: header (version, precision, frame and scene uniforms), the functions
 * the scene uses (each once), the IIS loop, and the entry point of the variant — `main` for WebGL2
 * (colour or probe) or `mainImage` for Shadertoy.
 */
import type { Scene } from '../../nodes/core/scene.ts';
import { type ColourSpace, shadesWithoutBlending, toSrgbGlsl } from './colour.glsl.ts';
import {
  clipTestGlsl,
  elementFunctions,
  emitBoundaryDistance,
  emitRunIis,
  needsEdgeDistance,
  orbitTrapDistanceGlsl,
  placeElements,
  shadeSampleGlsl,
  trapOf,
} from './iis.glsl.ts';
import { floatLiteral, intLiteral } from './literal.ts';
import { seedsGlsl } from './seeds.glsl.ts';
import { collectFunctions, type GlslFunction } from './snippet.ts';
import { SourceBuilder } from './source.ts';
import { declaration, PICTURE_SAMPLER, SceneValues, type UniformEntry } from './values.ts';
import { pixelToWorldGlsl, sampleOffsetGlsl } from './view.glsl.ts';

/**
 * color: linear RGBA of one sample. probe: the pure IIS loop, vec4(depth, final.x, final.y,
 * escaped) — what parity compares. inspect: what the picture decides at the point ("Explain this
 * pixel", shader-gen/trace.ts tracePicture): the clip disk and the orbit seeds apply, and w is the
 * stop reason, INSPECT_STOP.
 */
export type Variant = 'color' | 'probe' | 'inspect';

/** The inspect variant's w: 0 limit, 1 reached the tile, 2 outside the clip disk, 3 + k seed k. */
export const INSPECT_STOP = { limit: 0, tile: 1, clipped: 2, seed: 3 } as const;

/** Uniforms the runtime sets per frame, declared in every WebGL variant (names fixed). */
export const FRAME_UNIFORMS = [
  { name: 'u_resolution', type: 'vec2', doc: 'full image size in pixels' },
  {
    name: 'u_pixelOffset',
    type: 'vec2',
    doc: 'offset of this framebuffer within the full image (tiled export)',
  },
  { name: 'u_view', type: 'vec3', doc: 'view centre x, y and scale (world height of the image)' },
  { name: 'u_jitter', type: 'vec2', doc: 'sub-pixel sample offset in [0,1)² (view.ts sampleOffset)' },
  {
    name: 'u_bgAlpha',
    type: 'float',
    doc: 'alpha of the background outside the clip disk (1; 0 for transparent export)',
  },
] as const;

/** Attribute-less full-screen triangle: vertices (−1,−1), (3,−1), (−1,3) from gl_VertexID. */
export const VERTEX_SOURCE = `#version 300 es
void main() {
  vec2 corner = vec2(float((gl_VertexID << 1) & 2), float(gl_VertexID & 2));
  gl_Position = vec4(corner * 2.0 - 1.0, 0.0, 1.0);
}
`;

export interface EmittedShader {
  readonly source: string;
  readonly uniforms: UniformEntry[];
  readonly lineMap: Record<number, string>;
  /** The pictures' srcs by sampler number. */
  readonly pictures: string[];
}

/** The scene-dependent parts, with the uniforms they read registered in `v`; colours in `space`. */
function sceneParts(scene: Scene, v: SceneValues, variant: Variant, space: ColourSpace = 'linear') {
  const withColour = variant === 'color';
  const placed = placeElements(scene.elements, v);
  const maxIter = v.int('u_maxIterations', scene.maxIterations);
  const edges = withColour && needsEdgeDistance(scene);
  // The probe variant is the pure IIS loop (what parity compares): no seeds.
  const seedList = variant === 'probe' ? [] : (scene.tile.seeds ?? []);
  const seeds = seedList.length > 0 ? seedsGlsl(seedList, v, space) : null;
  const shadeSample = withColour ? shadeSampleGlsl(scene, v, seeds, space) : null;
  // The orbit trap only colours: the probe variant is the pure IIS loop.
  const trap = withColour ? trapOf(scene) : null;
  const trapCircle = trap ? v.vec('u_trap', [trap.c[0], trap.c[1], trap.r]) : null;
  const lineMap: Record<number, string> = {};
  scene.elements.forEach((e, i) => {
    lineMap[i + 1] = e.nodeId;
  });
  /** Writes the functions, the loop and shadeSample (colour only) after the header. */
  const emitBody = (out: SourceBuilder, extra: readonly GlslFunction[]) => {
    // Without shadeSample (inspect), runIis still calls seedAt.
    const shadeFns = shadeSample?.deps ?? (seeds ? [seeds.seedAt] : []);
    const fns = [
      ...elementFunctions(placed, edges),
      ...(trap ? [orbitTrapDistanceGlsl] : []),
      ...shadeFns,
      ...extra,
    ];
    for (const code of collectFunctions(fns)) out.push(code, '');
    emitRunIis(out, placed, maxIter, seeds?.seedAtArgs ?? null, trapCircle);
    out.push('');
    if (edges) {
      emitBoundaryDistance(out, placed);
      out.push('');
    }
    if (shadeSample) out.push(shadeSample.code, '');
  };
  return { emitBody, lineMap, pictures: v.pictures(), withSeeds: seeds !== null };
}

/**
 * `uniform sampler2D u_imageN;` for each picture (texture unit N, see SceneValues.picture). The
 * src stays out of the text: another picture is a new texture, not a new program.
 */
const samplerDeclarations = (pictures: readonly string[]) =>
  pictures.map((_, i) => `uniform sampler2D ${PICTURE_SAMPLER}${i};`);

/** A short, comment-safe name of a picture source (data: URLs are long). */
function describePicture(src: string): string {
  const comma = src.indexOf(',');
  const head = src.startsWith('data:') && comma > 0 ? src.slice(0, comma) : src;
  return head.replace(/[^A-Za-z0-9:/;._+-]/g, '').slice(0, 40);
}

const HEADER = ['precision highp float;', 'precision highp int;'];

export function fragmentShader(scene: Scene, variant: Variant, baked: boolean): EmittedShader {
  const v = new SceneValues(baked);
  const { emitBody, lineMap, pictures, withSeeds } = sceneParts(scene, v, variant);
  // Registered before the declarations are written (the inspect variant's main reads u_clip).
  const clipTest = variant === 'inspect' ? clipTestGlsl(scene, v) : [];
  const uniforms = v.entries();
  const out = new SourceBuilder().push('#version 300 es', ...HEADER, '');
  out.push('// Frame uniforms (set by the runtime).');
  for (const u of FRAME_UNIFORMS) out.push(`uniform ${u.type} ${u.name}; // ${u.doc}`);
  if (uniforms.length > 0) out.push('// Scene uniforms (values; changing them needs no recompile).');
  for (const u of uniforms) out.push(declaration(u));
  if (pictures.length > 0) out.push('// Pictures (textures; the runtime binds texture unit N to u_imageN).');
  out.push(...samplerDeclarations(pictures));
  out.push(
    variant === 'color'
      ? 'out vec4 outColor; // linear RGB; alpha u_bgAlpha on the background'
      : variant === 'probe'
        ? 'out vec4 outProbe; // (depth, final.x, final.y, escaped)'
        : 'out vec4 outProbe; // (depth, final.x, final.y, stop: 0 limit, 1 tile, 2 clipped, 3 + seed)',
    '',
  );
  emitBody(out, [pixelToWorldGlsl]);
  out.push(
    'void main() {',
    '  vec2 px = floor(gl_FragCoord.xy) + u_pixelOffset;',
    '  vec2 w = pixelToWorld(u_view, u_resolution, px, u_jitter);',
  );
  if (variant === 'color') out.push('  outColor = shadeSample(w, u_view.z / u_resolution.y, u_bgAlpha);');
  else if (variant === 'inspect') {
    const S = INSPECT_STOP;
    out.push(
      ...clipTest,
      `  if (clipped) { outProbe = vec4(0.0, w, ${floatLiteral(S.clipped)}); return; }`,
      '  vec2 p = w;',
      '  float s = 1.0;',
      '  int depth = 0;',
      '  int seed = -1;',
      withSeeds ? '  bool escaped = runIis(p, s, depth, seed);' : '  bool escaped = runIis(p, s, depth);',
      `  float stop = escaped ? ${floatLiteral(S.tile)} : seed >= 0 ? ${floatLiteral(S.seed)} + float(seed) : ${floatLiteral(S.limit)};`,
      '  outProbe = vec4(float(depth), p, stop);',
    );
  } else {
    out.push(
      '  vec2 p = w;',
      '  float s = 1.0;',
      '  int depth = 0;',
      '  bool escaped = runIis(p, s, depth);',
      '  outProbe = vec4(float(depth), p, escaped ? 1.0 : 0.0);',
    );
  }
  out.push('}');
  return { source: out.toString(), uniforms, lineMap, pictures };
}

/**
 * Shadertoy's `mainImage` (no #version, no uniforms: Shadertoy supplies iResolution): every value
 * baked, the view of the graph, `samples` jittered samples per pixel averaged in linear light and
 * encoded to sRGB. One sample of a tile that blends nothing (shadesWithoutBlending) is shaded in
 * sRGB and written as it is: no conversion at all. The image is a still: iTime is not used.
 */
export function shadertoyShader(scene: Scene): string {
  const count = Math.max(1, Math.round(scene.samples));
  const direct = count === 1 && shadesWithoutBlending(scene.tile);
  const v = new SceneValues(true);
  const { emitBody, pictures } = sceneParts(scene, v, 'color', direct ? 'srgb' : 'linear');
  const [cx, cy] = scene.view.center;
  const view = `vec3(${[cx, cy, scene.view.scale].map(floatLiteral).join(', ')})`;
  const out = new SourceBuilder(false).push(
    '// Kleinflow: an Iterated Inversion System, generated from a node graph. Paste into Shadertoy.',
    '',
  );
  // Shadertoy has no sampler uniforms of its own: picture N is read from iChannelN.
  pictures.forEach((src, i) => {
    out.push(`#define ${PICTURE_SAMPLER}${i} iChannel${i} // load ${describePicture(src)} there`);
  });
  if (pictures.length > 0) out.push('');
  const head = [
    'void mainImage(out vec4 fragColor, in vec2 fragCoord) {',
    `  vec3 view = ${view};`,
    '  vec2 px = floor(fragCoord);',
  ];
  if (count === 1) {
    // One sample at the pixel centre (sampleOffset(0) = (0.5, 0.5)).
    emitBody(out, direct ? [pixelToWorldGlsl] : [pixelToWorldGlsl, toSrgbGlsl]);
    const colour = 'shadeSample(w, view.z / iResolution.y, 1.0).rgb';
    out.push(
      ...head,
      '  vec2 w = pixelToWorld(view, iResolution.xy, px, vec2(0.5));',
      `  fragColor = vec4(${direct ? colour : `toSrgb(${colour})`}, 1.0);`,
      '}',
    );
    return out.toString();
  }
  emitBody(out, [pixelToWorldGlsl, sampleOffsetGlsl, toSrgbGlsl]);
  out.push(
    ...head,
    '  vec3 sum = vec3(0.0);',
    `  for (int k = 0; k < ${intLiteral(count)}; ++k) {`,
    '    vec2 w = pixelToWorld(view, iResolution.xy, px, sampleOffset(k));',
    '    sum += shadeSample(w, view.z / iResolution.y, 1.0).rgb;',
    '  }',
    `  fragColor = vec4(toSrgb(sum / ${floatLiteral(count)}), 1.0);`,
    '}',
  );
  return out.toString();
}
