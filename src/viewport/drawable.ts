/**
 * What the viewport draws: a 2D Scene (the IIS of the plane, compile.ts) or a 3D Scene3d (sphere
 * tracing, shader-gen/space/compile-3d.ts). Both become the same CompiledProgram shape, so the one
 * program cache, accumulation, idle bake and tiled export serve both (docs/architecture.md
 * "Uniforms and baked programs"). The 3D camera is not in the program at all: it is a frame
 * uniform like the 2D view (uniforms.ts), so orbiting never regenerates or recompiles anything.
 */
import { type Diagnostic, diag } from '../../nodes/core/diagnostics.ts';
import type { Scene } from '../../nodes/core/scene.ts';
import type { Scene3d } from '../../nodes/core/scene-3d.ts';
import { type CompiledProgram, type CompileOptions, compile } from '../../shader-gen/compile.ts';
import { compile3d } from '../../shader-gen/space/compile-3d.ts';
import { isScene3d } from '../../shader-gen/standalone.ts';

export type Drawable = Scene | Scene3d;

export const is3d: (d: Drawable) => d is Scene3d = isScene3d;

/** The 3D program in the 2D one's shape: no pictures, no per-element line map. */
function compile3dProgram(scene: Scene3d, baked: boolean): CompiledProgram {
  const { source, vertexSource, uniforms } = compile3d(scene, { bake: baked });
  return { source, vertexSource, uniforms, lineMap: {}, pictures: [], diagnostics: [] };
}

/** The program of `d`; a generator that throws (a bug, not a user error) is reported like a compile failure. */
export function generateProgram(d: Drawable, options: CompileOptions): CompiledProgram | Diagnostic[] {
  try {
    return is3d(d) ? compile3dProgram(d, options.baked === true) : compile(d, options);
  } catch (e) {
    return [diag('shaderCompile', {}, `shader generator: ${(e as Error).message}`)];
  }
}
