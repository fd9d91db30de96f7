/**
 * The material of a 3D orbit seed (docs/math-3d.md "Mirror material"): matte (lit, as before) or a
 * mirror whose reflectivity is Fresnel's F0. Every seed node spreads these into its spec and passes
 * its seed through `withMaterial`, so a mirror seed's whole orbit (all its images) is a mirror.
 */
import type { InputSpec, ParamSpec } from '../core/define-node.ts';
import { type Diagnostic, diag } from '../core/diagnostics.ts';
import type { Seed3d } from '../core/scene-3d.ts';
import { fmt } from './shared.ts';

export const MATERIAL_PARAM = {
  kind: 'enum',
  default: 'matte',
  options: ['matte', 'mirror'],
  label: 'material',
  doc: 'matte: lit by the light; mirror: reflects the other seeds and the environment (the Render 3D node’s reflections bound the bounces)',
} as const satisfies ParamSpec;

export const REFLECTIVITY_INPUT = {
  type: 'number',
  label: 'reflectivity',
  default: 0.8,
  step: 0.01,
  doc: 'how much a mirror reflects head-on, 0…1 (more at grazing angles: Fresnel)',
  when: { param: 'material', is: ['mirror'] },
} as const satisfies InputSpec;

/** The seed with its material: a mirror gets its reflectivity clamped into [0, 1] (saying so). */
export function withMaterial(
  seed: Seed3d,
  material: string,
  reflectivity: number,
): { seed: Seed3d; diagnostics: Diagnostic[] } {
  if (material !== 'mirror') return { seed, diagnostics: [] };
  const r = Number.isFinite(reflectivity) ? Math.min(1, Math.max(0, reflectivity)) : 0;
  const diagnostics =
    r === reflectivity
      ? []
      : [
          diag(
            'clamped',
            { port: 'reflectivity' },
            `reflectivity ${fmt(reflectivity)} is outside 0…1: ${fmt(r)} is used`,
          ),
        ];
  return { seed: { ...seed, reflectivity: r }, diagnostics };
}
