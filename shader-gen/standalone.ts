/**
 * The graph's shader as a file, the one generator behind `kleinflow glsl` and the editor's
 * Export → GLSL / Shadertoy: every value baked in, for the plane (compile.ts) or for space
 * (space/compile-3d.ts, the sphere tracer). `webgl2`: a standalone GLSL ES 3.00 fragment shader
 * (the frame uniforms, FRAME_UNIFORMS / FRAME_UNIFORMS_3D, are set by whoever draws it); `shadertoy`:
 * a `mainImage` that pastes into shadertoy.com (a 3D graph's camera baked too); `probe`: the
 * probe variant of the webgl2 shader.
 */
import type { Diagnostic } from '../nodes/core/diagnostics.ts';
import type { Scene } from '../nodes/core/scene.ts';
import type { Scene3d } from '../nodes/core/scene-3d.ts';
import { compile, shadertoySource } from './compile.ts';
import { compile3d, shadertoySource3d } from './space/compile-3d.ts';

export type StandaloneFlavour = 'webgl2' | 'shadertoy' | 'probe';

export interface StandaloneShader {
  readonly source: string;
  /** Compile notes (element or uniform limits); the shader is still usable. */
  readonly diagnostics: readonly Diagnostic[];
}

/** Whether a picture is of space (a render-3d graph) rather than of the plane. */
export const isScene3d = (d: Scene | Scene3d): d is Scene3d => 'kind' in d && d.kind === '3d';

export function standaloneShader(picture: Scene | Scene3d, flavour: StandaloneFlavour): StandaloneShader {
  if (isScene3d(picture)) {
    if (flavour === 'shadertoy') return { source: shadertoySource3d(picture), diagnostics: [] };
    const variant = flavour === 'probe' ? 'probe' : 'color';
    return { source: compile3d(picture, { bake: true, variant }).source, diagnostics: [] };
  }
  if (flavour === 'shadertoy') return { source: shadertoySource(picture), diagnostics: [] };
  const program = compile(picture, { baked: true, variant: flavour === 'probe' ? 'probe' : 'color' });
  return { source: program.source, diagnostics: program.diagnostics };
}
