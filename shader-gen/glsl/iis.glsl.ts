/**
 * The scene-specific GLSL: the IIS loop, the boundary distance over all elements and one sample's
 * colour, emitted as straight-line code per element (each block under its own `#line` marker).
 *
 *   runIis — the loop of interpret.ts runIis (math.md, normative): at depth ≥ maxIter only ask
 *   whether some element holds p (→ not escaped); else step the first element that holds p and
 *   restart from the first; no element holds p → escaped. Every pass either returns or adds ≥ 1
 *   to depth, so after at most maxIter passes depth ≥ maxIter.
 */
import type { Scene, SceneElement } from '../../nodes/core/scene.ts';
import { shadeGlsl } from './colour.glsl.ts';
import type { GlslElementTwin } from './element-twin.ts';
import { glslTwin } from './element-twins.ts';
import { type GlslFunction, glslFunction } from './snippet.ts';
import type { SourceBuilder } from './source.ts';
import type { SceneValues } from './values.ts';

/** Stands in for +∞ where the CPU starts a minimum at Infinity (GLSL ES has no literal for it). */
export const GLSL_FAR = '3.0e38';

interface PlacedElement {
  readonly element: SceneElement;
  readonly twin: GlslElementTwin;
  /** GLSL expressions of its data vec4s (`u_el[i]` or literals). */
  readonly data: readonly string[];
  /** The same, joined as trailing call arguments. */
  readonly args: string;
}

/** The elements with their data placed in `u_el` (or baked), in graph order. */
export function placeElements(elements: readonly SceneElement[], v: SceneValues): PlacedElement[] {
  return elements.map((element) => {
    const twin = glslTwin(element) as GlslElementTwin;
    const data = twin.pack(element);
    if (data.length !== twin.vec4s * 4) throw new Error(`${twin.kind} packed ${data.length} numbers`);
    const rows = v.elementRows(data);
    return { element, twin, data: rows, args: rows.join(', ') };
  });
}

/** Each kind's functions the loop calls (deduplicated by the assembler). */
export function elementFunctions(placed: readonly PlacedElement[], edges: boolean): GlslFunction[] {
  return placed.flatMap(({ twin }) => [
    ...twin.step.deps,
    twin.inside,
    ...(edges ? [twin.boundaryDistance] : []),
  ]);
}

/**
 * `bool runIis(inout vec2 p, inout float s, inout int depth)`: true when p escaped. The loop only
 * steps (each element's block: step it, and restart if it applied); once depth reaches maxIter
 * the blocks after the loop only ask whether some element holds p.
 */
export function emitRunIis(out: SourceBuilder, placed: readonly PlacedElement[], maxIter: string): void {
  out.push(
    'bool runIis(inout vec2 p, inout float s, inout int depth) {',
    `  for (int iteration = 0; iteration < ${maxIter}; ++iteration) {`,
    `    if (depth >= ${maxIter}) break;`,
  );
  placed.forEach(({ twin, data }, i) => {
    out.block(i + 1, [
      `    { // ${twin.kind}`,
      ...data.map((expr, k) => `      vec4 d${k} = ${expr};`),
      ...twin.step.code.split('\n').map((line) => `      ${line}`),
      '    }',
    ]);
  });
  out.push('    return true;', '  }', '  // depth ≥ maxIter: escaped only if no element holds p.');
  placed.forEach(({ twin, args }, i) => {
    out.block(i + 1, [`  if (${twin.inside.name}(p, ${args})) return false;`]);
  });
  out.push('  return true;', '}');
}

/** `float sceneBoundaryDistance(vec2 p)`: min over elements of boundaryDistance (raster.ts). */
export function emitBoundaryDistance(out: SourceBuilder, placed: readonly PlacedElement[]): void {
  out.push('float sceneBoundaryDistance(vec2 p) {', `  float d = ${GLSL_FAR};`);
  placed.forEach(({ twin, args }, i) => {
    out.block(i + 1, [`  d = min(d, ${twin.boundaryDistance.name}(p, ${args}));`]);
  });
  out.push('  return d;', '}');
}

/**
 * `vec4 shadeSample(vec2 w, float pixelWorld, float bgAlpha)`: raster.ts's per-sample body —
 * clip test, IIS run, edge distance in pixels (d / s / pixelWorld), shade; alpha is bgAlpha on
 * the background outside the clip disk, else 1. Returns shade's dependencies for the assembler.
 */
export function shadeSampleGlsl(scene: Scene, v: SceneValues): GlslFunction {
  const edges = scene.tile.edgeWidth > 0;
  const lines = ['vec4 shadeSample(vec2 w, float pixelWorld, float bgAlpha) {'];
  if (scene.clip) {
    const clip = v.vec('u_clip', [scene.clip.c[0], scene.clip.c[1], scene.clip.r]);
    lines.push(
      `  vec3 clip = ${clip};`,
      '  float cx = w.x - clip.x;',
      '  float cy = w.y - clip.y;',
      '  bool clipped = cx * cx + cy * cy > clip.z * clip.z;',
    );
  } else lines.push('  bool clipped = false;');
  lines.push(
    '  vec2 p = w;',
    '  float s = 1.0;',
    '  int depth = 0;',
    '  bool escaped = clipped ? false : runIis(p, s, depth);',
    `  float edgePixels = ${GLSL_FAR};`,
  );
  if (edges) lines.push('  if (escaped) edgePixels = sceneBoundaryDistance(p) / s / pixelWorld;');
  lines.push('  return vec4(shade(clipped, escaped, depth, edgePixels), clipped ? bgAlpha : 1.0);', '}');
  return glslFunction('shadeSample', lines.join('\n'), [shadeGlsl(scene.tile, v)]);
}
