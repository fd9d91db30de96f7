/**
 * Scene → one GLSL ES 3.00 fragment shader (plus its full-screen-triangle vertex shader).
 * Passes: check limits → place element data (uniform array or literals) → emit the functions the
 * scene uses, the IIS loop with one straight-line block per element, and the variant's main →
 * assemble with `#line` markers. Deterministic: the same scene gives the same text byte for byte.
 */
import { type Diagnostic, diag } from '../nodes/core/diagnostics.ts';
import { LIMITS, type Scene } from '../nodes/core/scene.ts';
import {
  FRAME_UNIFORMS,
  fragmentShader,
  shadertoyShader,
  type Variant,
  VERTEX_SOURCE,
} from './glsl/template.ts';
import { type UniformEntry, uniformRows } from './glsl/values.ts';
import { firstOutOfGpuRange } from './gpu-range.ts';

export { FRAME_UNIFORMS, INSPECT_STOP } from './glsl/template.ts';
export type { UniformEntry } from './glsl/values.ts';

export interface CompileOptions {
  /**
   * color: linear RGBA of one sample; probe: vec4(depth, final.x, final.y, escaped) (RGBA32F);
   * inspect: vec4(depth, final.x, final.y, stop) with the clip disk and seeds (INSPECT_STOP).
   */
  variant?: Variant;
  /** Every scene value inlined as a literal (no scene uniforms). */
  baked?: boolean;
}

export interface CompiledProgram {
  /**
   * Full fragment shader, starting with "#version 300 es". It is also the program's identity: the
   * runtime caches linked programs by this text, so a value edit (the same text, new uniforms)
   * never recompiles and any change of the code always does — no second list of "what changes
   * the code" to keep in step with the generator.
   */
  source: string;
  /** The full-screen triangle vertex shader (attribute-less, gl_VertexID). */
  vertexSource: string;
  /** Scene values to upload (empty when baked); sorted by name; all finite. */
  uniforms: UniformEntry[];
  /** `#line` source-string number → id of the node that produced that element. */
  lineMap: Record<number, string>;
  /**
   * The pictures' srcs by sampler: texture unit N must hold pictures[N] (sampler `u_imageN`),
   * uploaded as SRGB8_ALPHA8, LINEAR filtering, REPEAT wrap, row 0 = the top row.
   */
  pictures: string[];
  diagnostics: Diagnostic[];
}

/** Uniform rows the frame uniforms take (each its own row, see uniformRows). */
const FRAME_ROWS = FRAME_UNIFORMS.length;

/** The scene limited to LIMITS.maxElements elements, with a diagnostic when it had more. */
function withinElementLimit(scene: Scene, diagnostics: Diagnostic[]): Scene {
  if (scene.elements.length <= LIMITS.maxElements) return scene;
  const nodeId = scene.elements[LIMITS.maxElements].nodeId;
  diagnostics.push(diag('tooManyElements', { nodeId }, scene.elements.length, LIMITS.maxElements));
  return { ...scene, elements: scene.elements.slice(0, LIMITS.maxElements) };
}

export function compile(input: Scene, options: CompileOptions = {}): CompiledProgram {
  const variant = options.variant ?? 'color';
  const diagnostics: Diagnostic[] = [];
  const scene = withinElementLimit(input, diagnostics);
  const far = firstOutOfGpuRange(scene);
  if (far) diagnostics.push(diag('gpuRange', { nodeId: far.nodeId }, far.value, LIMITS.gpuMaxMagnitude));
  let baked = options.baked ?? false;
  let emitted = fragmentShader(scene, variant, baked);
  if (!baked) {
    const rows = FRAME_ROWS + emitted.uniforms.reduce((n, u) => n + uniformRows(u), 0);
    if (rows > LIMITS.maxUniformVectors) {
      // Too much data for the uniforms every WebGL2 GPU has: literals have no such limit.
      diagnostics.push(
        diag('uniformBudget', { nodeId: scene.renderNodeId ?? undefined }, rows, LIMITS.maxUniformVectors),
      );
      baked = true;
      emitted = fragmentShader(scene, variant, baked);
    }
  }
  return {
    source: emitted.source,
    vertexSource: VERTEX_SOURCE,
    uniforms: emitted.uniforms,
    lineMap: emitted.lineMap,
    pictures: emitted.pictures,
    diagnostics,
  };
}

/** The `mainImage` version with every value baked in: pastes into Shadertoy unchanged. */
export function shadertoySource(scene: Scene): string {
  return shadertoyShader(withinElementLimit(scene, []));
}
