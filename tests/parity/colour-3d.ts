/**
 * What the 3D parity files share (trace3d-, volume3d- and mirror-parity.test.ts): drawing a scene
 * with one of compile3d's programs from its own camera, and comparing the colour program's linear
 * RGB with a CPU colour pixel by pixel (the largest channel difference per pixel, then its median
 * and 95th percentile over the compared pixels).
 */
import type { Scene3d } from '../../nodes/core/scene-3d.ts';
import { type Compile3dOptions, cameraUniforms, compile3d } from '../../shader-gen/space/compile-3d.ts';
import { prepareTrace3d, type TracePlan } from '../../shader-gen/space/plan.ts';
import { tracePixel } from '../../shader-gen/space/render-3d.ts';
import type { GpuProbe, ProbeImage } from './gpu-probe.ts';

/** `scene` drawn by compile3d's program (`options`) from the scene's camera, over the whole frame. */
export async function render3d(
  gpu: GpuProbe,
  scene: Scene3d,
  options: Compile3dOptions = {},
): Promise<ProbeImage> {
  const program = compile3d(scene, options);
  const index = await gpu.program(program.vertexSource, program.source);
  return gpu.render(index, [...program.uniforms, ...cameraUniforms(scene.camera)], {
    center: [0, 0],
    scale: 1,
  });
}

/** The ray of one pixel centre and what the CPU tracer hit along it (render-3d.ts tracePixel). */
export type TracedPixel = ReturnType<typeof tracePixel>;

export interface ColourDiffs {
  /** How many pixels were compared. */
  readonly pixels: number;
  readonly median: number;
  readonly p95: number;
}

/**
 * The colour program's linear RGB against `cpuColour` at the centres of every `step`-th pixel in x
 * and y of the probe's frame. `cpuColour` gets the CPU trace of the pixel and the GPU's alpha there,
 * and returns null to leave the pixel out.
 */
export async function colourDiffs3d(
  gpu: GpuProbe,
  scene: Scene3d,
  step: number,
  cpuColour: (plan: TracePlan, pixel: TracedPixel, gpuAlpha: number) => readonly number[] | null,
): Promise<ColourDiffs> {
  const image = await render3d(gpu, scene);
  const { width, height } = gpu;
  const plan = prepareTrace3d(scene);
  const diffs: number[] = [];
  for (let py = 0; py < height; py += step) {
    for (let px = 0; px < width; px += step) {
      const o = 4 * (py * width + px);
      const cpu = cpuColour(plan, tracePixel(plan, width, height, px + 0.5, py + 0.5), image.data[o + 3]!);
      if (!cpu) continue;
      diffs.push(Math.max(...[0, 1, 2].map((k) => Math.abs(cpu[k]! - image.data[o + k]!))));
    }
  }
  diffs.sort((a, b) => a - b);
  return {
    pixels: diffs.length,
    median: diffs[Math.floor(diffs.length / 2)]!,
    p95: diffs[Math.floor(diffs.length * 0.95)]!,
  };
}
