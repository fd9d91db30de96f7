/**
 * The 3D render node: the elements and orbit seeds of space, the camera, the sphere-tracing budget,
 * the lighting and the colouring (docs/math-3d.md §7), or the volume mode (render-3d-volume.ts). Its evaluate returns the settings; the
 * evaluator makes them the Evaluation's `scene3d`. Out-of-range numbers are clamped with a
 * message (never an error: the picture keeps drawing while a slider passes through).
 */

import { defineNode } from '../core/define-node.ts';
import { type Diagnostic, diag } from '../core/diagnostics.ts';
import { LIMITS } from '../core/limits.ts';
import { toHex } from '../core/port-values.ts';
import {
  type Coloring3d,
  DEFAULT_CAMERA_3D,
  DEFAULT_LIGHTING_3D,
  type Lighting3d,
  MAX_REFLECTIONS,
  type NodeElement3d,
  type Seed3d,
} from '../core/scene-3d.ts';
import { DEFAULT_COLORING } from '../core/tile-spec.ts';
import type { Color } from '../core/values.ts';
import { formulaFor } from '../formula/checked.ts';
import { COLOUR_3D_NAMES } from '../formula/names.ts';
import { MAX_FORMULA_LENGTH } from '../formula/parse.ts';
import { dist3, len3 } from '../geometry/space/vec3.ts';
import { PALETTES } from './colour.ts';
import { ENVIRONMENT_PARAMS, environment3d, REFLECTIONS_INPUT } from './environment-3d.ts';
import { VOLUME_INPUTS, VOLUME_PARAMS, volumeSettings } from './render-3d-volume.ts';
import { fail, fmt } from './shared.ts';
import { cameraDiagnostics, gpuRangeDiagnostics3d, seedDiagnostics } from './space-checks.ts';
import { element3Input, point3Input } from './space-shared.ts';

const [cx, cy, cz] = DEFAULT_CAMERA_3D.position;
const [tx, ty, tz] = DEFAULT_CAMERA_3D.target;
const [lx, ly, lz] = DEFAULT_LIGHTING_3D.direction;

/** A number input clamped by the node (no min/max in the spec: out of range is a warning, not an error). */
const setting = (label: string, value: number, doc: string, more?: true) =>
  ({ type: 'number', label, default: value, doc, ...(more ? { more } : {}) }) as const;

/**
 * Fields that mean something only to the sphere tracer (colouring, lighting, marching, mirrors and
 * their environment): hidden while `render` is volume, whose picture they do not touch (the volume
 * has its own palette and lies over the flat background; docs/math-3d.md §11). Fields that depend on
 * the colouring or the environment are hidden with them (field-visibility.ts follows the chain).
 */
const WHEN_SURFACE = { param: 'render', is: ['surface'] } as const;
/** A sphere-tracer setting under "More". */
const surfaceSetting = (label: string, value: number, doc: string) =>
  ({ ...setting(label, value, doc, true), when: WHEN_SURFACE }) as const;

/** The palette colours of the "custom" palette (the palette itself shows only in PALETTED modes). */
const colour = (hex: string, label: string) =>
  ({ type: 'color', label, default: hex, when: { param: 'palette', is: ['custom'] } }) as const;

/** The colourings a palette colours: by depth (cosine) and by a measure of the hit point. */
const PALETTED = ['cosine', 'distance', 'argument', 'formula'];
/** The measured colourings (shader-gen/space/shade-3d.ts measureColour3d). */
const MEASURED = ['distance', 'argument', 'formula'];

/** The formula colouring's default: bands by depth, turned by the hit point's height. */
export const COLOUR_FORMULA_3D = 'n / 6 + 0.5 * z';

/** Clamps v into [lo, hi] (rounded when `integer`), saying so when it changes. */
function clampTo(
  name: string,
  v: number,
  lo: number,
  hi: number,
  out: Diagnostic[],
  integer = false,
): number {
  const c = Math.min(hi, Math.max(lo, integer ? Math.round(v) : v));
  if (c !== v)
    out.push(
      diag(
        'clamped',
        { port: name },
        `${name} ${fmt(v)} is outside ${fmt(lo)}…${fmt(hi)}${integer ? ' (whole numbers)' : ''}: ${fmt(c)} is used`,
      ),
    );
  return c;
}

interface ColoringInputs {
  readonly step: number;
  readonly scale: number;
  readonly cycles: number;
  readonly offset: number;
  readonly a: Color;
  readonly b: Color;
  readonly c: Color;
  readonly d: Color;
}

/**
 * The Coloring3d of a mode and palette: the wheel by depth is the depth-wheel; a named palette
 * replaces a, b, c, d; distance has 1/scale palette steps per world unit, argument `cycles` per turn.
 */
function coloring3d(mode: string, palette: string, i: ColoringInputs, formula: string): Coloring3d {
  const scale = i.scale > 0 ? i.scale : 1;
  const wheel = palette === 'wheel';
  const { a, b, c, d } = PALETTES[palette] ?? i;
  switch (mode) {
    case 'cosine':
      return wheel ? { mode: 'depth-wheel', step: i.step } : { mode, a, b, c, d, step: i.step };
    case 'distance':
    case 'argument': {
      const frequency = mode === 'distance' ? 1 / scale : i.cycles;
      return { mode, wheel, a, b, c, d, frequency, offset: i.offset };
    }
    case 'formula':
      return { mode, wheel, a, b, c, d, frequency: 1, offset: i.offset, formula };
    case 'surface':
    case 'final-point':
      return { mode, scale };
    default:
      return { mode: 'depth-wheel', step: i.step };
  }
}

export const render3dNode = defineNode({
  type: 'render-3d',
  version: 1,
  label: 'Render 3D',
  category: 'Output',
  color: '#ffffff',
  doc: 'The 3D picture: sphere-traces the orbits of the seeds under every 3D element wired in (tested in graph order), lit and coloured — or, with render: volume, draws the nesting depth of the mirrors as a translucent cloud (Fig. 10).',
  inputs: {
    elements: element3Input('elements'),
    seeds: { type: 'seed3', label: 'seeds', optional: true, doc: 'the shapes whose images are drawn' },
    limitSets: {
      type: 'limit3',
      label: 'limit sets',
      optional: true,
      doc: 'quaternion Kleinian groups whose limit sets are drawn as dots over the picture',
    },
    camera: point3Input('camera', cx, cy, cz, 'where the eye is (z is up)'),
    target: point3Input('look at', tx, ty, tz, 'the point the camera looks at'),
    fov: setting('field of view °', DEFAULT_CAMERA_3D.fovDeg, 'vertical field of view, 1°…170°'),
    maxIterations: setting(
      'max iterations',
      LIMITS.defaultMaxIterations3d,
      'IIS steps per distance estimate',
    ),
    marchSteps: surfaceSetting('march steps', LIMITS.defaultMarchSteps, 'sphere-tracing steps per ray'),
    deScale: surfaceSetting(
      'DE scale',
      1,
      'each march step goes this fraction (≤ 1) of the distance estimate',
    ),
    reflections: { ...REFLECTIONS_INPUT, when: WHEN_SURFACE },
    samples: setting('samples / pixel', 4, 'anti-aliasing samples when the view is still', true),
    step: {
      type: 'number',
      label: 'colour step',
      default: 0.1,
      doc: 'colour change per inversion (turns of the wheel, or palette steps)',
      when: { param: 'coloring', is: ['depth-wheel', 'cosine'] },
    },
    scale: {
      type: 'number',
      label: 'colour scale',
      default: 1,
      doc: 'world units per colour cycle',
      when: { param: 'coloring', is: ['surface', 'final-point', 'distance'] },
    },
    cycles: {
      type: 'number',
      label: 'colour cycles',
      default: 1,
      doc: 'palette cycles per turn about the z axis',
      when: { param: 'coloring', is: ['argument'] },
    },
    offset: {
      type: 'number',
      label: 'colour offset',
      default: 0,
      doc: 'where the palette starts (palette steps, or turns of the wheel)',
      when: { param: 'coloring', is: MEASURED },
    },
    a: colour(toHex(DEFAULT_COLORING.a), 'a (centre)'),
    b: colour(toHex(DEFAULT_COLORING.b), 'b (swing)'),
    c: colour(toHex(DEFAULT_COLORING.c), 'c (frequency)'),
    d: colour(toHex(DEFAULT_COLORING.d), 'd (phase)'),
    light: {
      ...point3Input('light direction', lx, ly, lz, 'direction towards the light'),
      more: true,
      when: WHEN_SURFACE,
    },
    ambient: surfaceSetting('ambient', DEFAULT_LIGHTING_3D.ambient, '0…1'),
    diffuse: surfaceSetting('diffuse', DEFAULT_LIGHTING_3D.diffuse, '0…1'),
    specular: surfaceSetting('specular', DEFAULT_LIGHTING_3D.specular, '0…1'),
    shininess: surfaceSetting('shininess', DEFAULT_LIGHTING_3D.shininess, 'highlight exponent, 1…512'),
    occlusion: surfaceSetting('occlusion', DEFAULT_LIGHTING_3D.occlusion, 'ambient-occlusion strength, 0…1'),
    shadow: surfaceSetting('shadow', DEFAULT_LIGHTING_3D.shadow, 'soft-shadow strength, 0…1'),
    ...VOLUME_INPUTS,
  },
  outputs: {},
  params: {
    // `render` first: it shows or hides the colouring and environment switches, so it stays put.
    render: VOLUME_PARAMS.render,
    coloring: {
      kind: 'enum',
      default: 'depth-wheel',
      when: WHEN_SURFACE,
      options: ['depth-wheel', 'cosine', 'surface', 'final-point', 'distance', 'argument', 'formula'],
      label: 'colouring',
      doc: 'depth-wheel: the seed colour turned by the depth; cosine: a palette by depth; surface: by the hit point; final-point: by where the IIS ends; distance / argument: a palette by the hit point’s distance from the origin / angle about the z axis; formula: a palette by your formula of the hit point and depth',
    },
    formula: {
      kind: 'string',
      default: COLOUR_FORMULA_3D,
      maxLength: MAX_FORMULA_LENGTH,
      label: 'colour formula',
      doc: 'formula colouring: a formula of the hit point x, y, z and the depth n; palette t = offset + it',
      when: { param: 'coloring', is: ['formula'] },
    },
    palette: {
      kind: 'enum',
      // "custom" by default: documents saved before presets keep their own a, b, c, d.
      default: 'custom',
      options: ['custom', 'wheel', ...Object.keys(PALETTES)],
      label: 'palette',
      doc: 'a named cosine palette, "wheel" (the seed colour’s hue turned), or "custom" to set a, b, c, d yourself',
      when: { param: 'coloring', is: PALETTED },
    },
    background: { kind: 'color', default: '#101018', label: 'background' },
    ...ENVIRONMENT_PARAMS,
    environment: { ...ENVIRONMENT_PARAMS.environment, when: WHEN_SURFACE },
    volumePalette: VOLUME_PARAMS.volumePalette,
  },
  evaluate: ({ inputs: i, params, nodeId }) => {
    const diagnostics: Diagnostic[] = [];
    if (params.coloring === 'formula') {
      const checked = formulaFor(
        nodeId,
        params.formula,
        COLOUR_3D_NAMES,
        ['number'],
        'a colour formula gives a number',
      );
      if ('problem' in checked) return { diagnostics: [checked.problem] };
    }
    if (!(dist3(i.camera, i.target) > 0))
      return fail('the camera and the point it looks at coincide: there is no view direction');
    let elements: readonly NodeElement3d[] = i.elements;
    if (elements.length > LIMITS.maxElements) {
      diagnostics.push({
        ...diag('tooManyElements', { port: 'elements' }, elements.length, LIMITS.maxElements),
        severity: 'warning',
      });
      elements = elements.slice(0, LIMITS.maxElements);
    }
    let seeds: readonly Seed3d[] = i.seeds;
    if (seeds.length > LIMITS.maxSeeds) {
      diagnostics.push(diag('tooManySeeds', { port: 'seeds' }, seeds.length, LIMITS.maxSeeds));
      seeds = seeds.slice(0, LIMITS.maxSeeds);
    }
    // The volume mode draws the mirrors' nesting depth, limit sets draw themselves: neither needs seeds.
    if (seeds.length === 0 && i.limitSets.length === 0 && params.render !== 'volume')
      diagnostics.push({
        ...diag('clamped', { port: 'seeds' }, 'no seeds wired in: there is nothing to draw'),
        severity: 'info',
      });
    const camera = {
      position: i.camera,
      target: i.target,
      fovDeg: clampTo('fov', i.fov, 1, 170, diagnostics),
    };
    diagnostics.push(
      ...cameraDiagnostics(camera.position, elements, seeds),
      ...seedDiagnostics(seeds, elements),
      ...gpuRangeDiagnostics3d(elements, seeds, [camera.position, camera.target]),
    );
    const light = len3(i.light) > 0 ? i.light : DEFAULT_LIGHTING_3D.direction;
    if (light !== i.light)
      diagnostics.push(
        diag('clamped', { port: 'light' }, 'the light direction is zero: the default direction is used'),
      );
    const unit = (name: string, v: number) => clampTo(name, v, 0, 1, diagnostics);
    const lighting: Lighting3d = {
      direction: light,
      ambient: unit('ambient', i.ambient),
      diffuse: unit('diffuse', i.diffuse),
      specular: unit('specular', i.specular),
      shininess: clampTo('shininess', i.shininess, 1, 512, diagnostics),
      occlusion: unit('occlusion', i.occlusion),
      shadow: unit('shadow', i.shadow),
    };
    const coloring = coloring3d(params.coloring, params.palette, i, params.formula);
    if (['surface', 'final-point', 'distance'].includes(params.coloring) && !(i.scale > 0))
      diagnostics.push(
        diag('clamped', { port: 'scale' }, `colour scale ${fmt(i.scale)} is not positive: 1 is used`),
      );
    const settings = {
      elements,
      seeds,
      camera,
      maxIterations: clampTo('maxIterations', i.maxIterations, 1, LIMITS.maxIterations, diagnostics, true),
      marchSteps: clampTo('marchSteps', i.marchSteps, 1, LIMITS.maxMarchSteps, diagnostics, true),
      deScale: clampTo('deScale', i.deScale, 0.01, 1, diagnostics),
      lighting,
      coloring,
      background: params.background,
      environment: environment3d(params.environment, params.horizon, params.ground),
      reflections: clampTo('reflections', i.reflections, 0, MAX_REFLECTIONS, diagnostics, true),
      samples: clampTo('samples', i.samples, 1, LIMITS.maxSamples, diagnostics, true),
      ...(i.limitSets.length > 0 ? { limitSets: i.limitSets } : {}),
    };
    const volume = volumeSettings(i, params, (name, v, lo, hi, integer) =>
      clampTo(name, v, lo, hi, diagnostics, integer),
    );
    const plural = (n: number, w: string) => `${n} ${w}${n === 1 ? '' : 's'}`;
    return {
      outputs: {},
      diagnostics,
      readout: `${plural(elements.length, 'element')}, ${plural(seeds.length, 'seed')}${
        i.limitSets.length > 0 ? `, ${plural(i.limitSets.length, 'limit set')}` : ''
      }`,
      render3d: volume ? { ...settings, volume } : settings,
    };
  },
});
