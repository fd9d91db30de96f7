/**
 * "Explain this pixel" for a volume-rendered 3D graph (Render 3D's render: volume, docs/math-3d.md
 * "§11 Volume rendering of the nesting depth"): the ray through the clicked pixel integrated by the
 * CPU volume renderer itself (shader-gen/space/explain-volume-3d.ts) — the samples it took, the
 * nesting depths it crossed as runs, each with the colour its depth emits, the opacity reached,
 * whether it stopped early, and the pixel's colour — with a sentence saying it in words.
 */
import { toHex } from '../../../nodes/core/port-values.ts';
import type { Camera3d, Scene3d, Volume3d } from '../../../nodes/core/scene-3d.ts';
import { explainVolumePixel3d, type VolumeTrace3d } from '../../../shader-gen/space/explain-volume-3d.ts';
import { EXIT_TRANSMITTANCE, transferPlace, volumeColour } from '../../../shader-gen/space/volume-3d.ts';
import { linearToSrgb } from '../../../shader-gen/srgb.ts';
import type { GpuCheck } from './inspection.ts';

/** A run of samples at one depth, as the panel lists it. */
export interface DepthRunView {
  readonly depth: number;
  readonly samples: number;
  /** The colour this depth emits ("#rrggbb"), or null where it is shallower than `from depth` (empty). */
  readonly color: string | null;
  /** Whether the depth is the walk's whole budget (on or near the limit set). */
  readonly atLimit: boolean;
}

export interface InspectionVolume {
  readonly kind: 'volume';
  readonly trace: VolumeTrace3d;
  readonly runs: readonly DepthRunView[];
  /** The pixel's colour, "#rrggbb". */
  readonly color: string;
  readonly stopText: string;
  readonly gpu: GpuCheck;
}

const GPU_VOLUME: GpuCheck = {
  kind: 'unavailable',
  reason: 'the CPU volume renderer, the picture’s tested twin, explains the pixel',
};

const percent = (x: number) => `${+(100 * x).toFixed(x > 0.99 && x < 1 ? 1 : 0)} %`;
const plural = (n: number, one: string) => `${n} ${one}${n === 1 ? '' : 's'}`;

/** The emitted colour of depth k, as the panel shows it (null: shallower than `from depth`). */
function depthColor(v: Volume3d, depth: number): string | null {
  if (depth < v.depthFrom) return null;
  const c = volumeColour(v, transferPlace(v, depth));
  return toHex([linearToSrgb(c[0]), linearToSrgb(c[1]), linearToSrgb(c[2])]);
}

/** The sentence for what the ray did in the volume. */
function volumeSentence(t: VolumeTrace3d, v: Volume3d): string {
  if (!t.span)
    return 'The camera ray passes outside the ball holding every mirror: no sample has any depth, the pixel shows the background.';
  const shown = t.runs.some((r) => r.depth >= v.depthFrom);
  const took = `The camera ray crosses the volume in ${plural(t.samples, 'sample')}`;
  if (!shown)
    return `${took}, all shallower than depth ${v.depthFrom} (from depth): the medium is empty there, the pixel shows the background.`;
  const deepest = `, down to nesting depth ${t.deepest}`;
  if (t.exitedEarly)
    return `${took}${deepest}. It became ${percent(1 - EXIT_TRANSMITTANCE)} opaque after sample ${t.samples} of ${t.steps} and stopped early: what lies behind does not show.`;
  return `${took}${deepest}, and is ${percent(t.opacity)} opaque at the end: the rest of the pixel is the background showing through.`;
}

/**
 * Explains the CSS point (x, y) of a width × height 3D view of a volume-rendered scene seen through
 * `camera` (the view's, which may differ from the render node's).
 */
export function inspectVolume(
  scene: Scene3d,
  camera: Camera3d,
  css: readonly [number, number],
  width: number,
  height: number,
): InspectionVolume {
  const v = scene.volume;
  if (!v) throw new Error('inspectVolume needs a volume-rendered scene');
  const t = explainVolumePixel3d({ ...scene, camera }, width, height, css[0], height - css[1]);
  const runs = t.runs.map(
    (r): DepthRunView => ({
      depth: r.depth,
      samples: r.samples,
      color: depthColor(v, r.depth),
      atLimit: r.depth >= scene.maxIterations,
    }),
  );
  return {
    kind: 'volume',
    trace: t,
    runs,
    color: toHex(t.colour),
    stopText: volumeSentence(t, v),
    gpu: GPU_VOLUME,
  };
}
