/**
 * The Render 3D node's reflection settings (docs/math-3d.md "Mirror material"): how many bounces a
 * ray takes off mirror seeds, and the environment that rays hitting nothing see — the primary rays
 * (the background) and the reflected rays alike, so a mirror reflects the picture's own sky.
 */
import type { InputSpec, ParamSpec } from '../core/define-node.ts';
import { DEFAULT_REFLECTIONS, type Environment3d, MAX_REFLECTIONS } from '../core/scene-3d.ts';
import type { Color } from '../core/values.ts';

const SKY = { param: 'environment', is: ['sky'] } as const;

export const REFLECTIONS_INPUT = {
  type: 'number',
  label: 'reflections',
  default: DEFAULT_REFLECTIONS,
  doc: `bounces a ray may take off mirror seeds, 0…${MAX_REFLECTIONS} (0: mirrors are drawn matte)`,
} as const satisfies InputSpec;

export const ENVIRONMENT_PARAMS = {
  environment: {
    kind: 'enum',
    default: 'flat',
    options: ['flat', 'sky'],
    label: 'environment',
    doc: 'what rays that hit nothing see, directly or in a mirror: flat, the background colour; sky, a gradient from the horizon up to the background colour, and the ground below',
  },
  horizon: { kind: 'color', default: '#c9d6e8', label: 'horizon', when: SKY },
  ground: { kind: 'color', default: '#3a342e', label: 'ground', when: SKY },
} as const satisfies Record<string, ParamSpec>;

export const environment3d = (mode: string, horizon: Color, ground: Color): Environment3d =>
  mode === 'sky' ? { mode: 'sky', horizon, ground } : { mode: 'flat' };
