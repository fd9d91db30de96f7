/**
 * The 3D programs that compile-3d.test.ts and volume-glsl.test.ts give glslangValidator: for each
 * named scene, compile3d's program in each named variant (`scene.variant`) and its Shadertoy
 * version (`scene.shadertoy`), then the hand-written bench programs (`hand-written-example`).
 */
import type { Scene3d } from '../../../nodes/core/scene-3d.ts';
import { type Compile3dOptions, compile3d, shadertoySource3d } from '../../../shader-gen/space/compile-3d.ts';
import { type ShaderToCheck, shadertoyWrapper } from '../support/glslang.ts';

export function shaders3d(
  scenes: Record<string, Scene3d>,
  variants: Record<string, Compile3dOptions>,
  handWritten: readonly { readonly example: string; readonly source: string }[],
): ShaderToCheck[] {
  return [
    ...Object.entries(scenes).flatMap(([name, scene]) => [
      ...Object.entries(variants).map(([variant, options]) => ({
        name: `${name}.${variant}`,
        source: compile3d(scene, options).source,
        stage: 'frag' as const,
      })),
      {
        name: `${name}.shadertoy`,
        source: shadertoyWrapper(shadertoySource3d(scene)),
        stage: 'frag' as const,
      },
    ]),
    ...handWritten.map(({ example, source }) => ({
      name: `hand-written-${example}`,
      source,
      stage: 'frag' as const,
    })),
  ];
}
