/**
 * The Render 3D node's volume mode (paper §4.2, Fig. 10; docs/math-3d.md "§11 Volume rendering of
 * the nesting depth"): its inputs and params, shown while `render` is "volume", and the Volume3d
 * they make. Every number is a uniform of the generated shader (dragging one never recompiles).
 */
import type { Volume3d } from '../core/scene-3d.ts';
import { PALETTES } from './colour.ts';

const whenVolume = { param: 'render', is: ['volume'] } as const;

const volumeSetting = (label: string, value: number, doc: string) =>
  ({ type: 'number', label, default: value, doc, when: whenVolume }) as const;

/** Bounds of the volume numbers: out of range is clamped with a message, like the node's others. */
export const VOLUME_LIMITS = {
  steps: [4, 1024],
  density: [0, 1000],
  growth: [0.1, 16],
  depth: [1, 1000],
} as const;

export const VOLUME_INPUTS = {
  volumeSteps: volumeSetting('volume samples', 96, 'samples along each ray (the quality), 4…1024'),
  density: volumeSetting('density', 0.25, 'extinction per world unit at the first depth shown'),
  growth: volumeSetting('density growth', 3, 'factor of the density per level deeper, 0.1…16'),
  depthFrom: volumeSetting('from depth', 1, 'the shallowest nesting depth shown (≥ 1)'),
  depthTo: volumeSetting('to depth', 5, 'the depth where the palette ends and the density stops growing'),
} as const;

export const VOLUME_PARAMS = {
  render: {
    kind: 'enum',
    default: 'surface',
    options: ['surface', 'volume'],
    label: 'render',
    doc: 'surface: sphere-trace the seed images; volume: a translucent cloud of the nesting depth of the mirrors (Fig. 10)',
  },
  volumePalette: {
    kind: 'enum',
    default: 'rainbow',
    options: Object.keys(PALETTES),
    label: 'volume palette',
    doc: 'the named cosine palette the depth runs through',
    when: whenVolume,
  },
} as const;

type Clamp = (name: string, v: number, lo: number, hi: number, integer?: boolean) => number;

interface VolumeInputs {
  readonly volumeSteps: number;
  readonly density: number;
  readonly growth: number;
  readonly depthFrom: number;
  readonly depthTo: number;
}

/** The Volume3d of the inputs (clamped by `clamp`, which reports), or undefined in surface mode. */
export function volumeSettings(
  i: VolumeInputs,
  params: { readonly render: string; readonly volumePalette: string },
  clamp: Clamp,
): Volume3d | undefined {
  if (params.render !== 'volume') return undefined;
  const L = VOLUME_LIMITS;
  const depthFrom = clamp('depthFrom', i.depthFrom, L.depth[0], L.depth[1], true);
  const { a, b, c, d } = PALETTES[params.volumePalette] ?? PALETTES.rainbow!;
  return {
    steps: clamp('volumeSteps', i.volumeSteps, L.steps[0], L.steps[1], true),
    density: clamp('density', i.density, L.density[0], L.density[1]),
    growth: clamp('growth', i.growth, L.growth[0], L.growth[1]),
    depthFrom,
    depthTo: clamp('depthTo', i.depthTo, depthFrom, L.depth[1], true),
    a,
    b,
    c,
    d,
  };
}
