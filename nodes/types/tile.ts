import { defineNode, type FieldCondition, type InputSpec, type ParamSpec } from '../core/define-node.ts';
import { diag } from '../core/diagnostics.ts';
import { LIMITS } from '../core/limits.ts';
import { toHex } from '../core/port-values.ts';
import {
  type Coloring,
  DEFAULT_COLORING,
  DEFAULT_TILE,
  type Measure,
  type TileSpec,
} from '../core/tile-spec.ts';
import { BUILTIN_PICTURE, type Color, type Vec2 } from '../core/values.ts';
import { formulaFor } from '../formula/checked.ts';
import { COLOUR_NAMES } from '../formula/names.ts';
import { MAX_FORMULA_LENGTH } from '../formula/parse.ts';
import { dist } from '../geometry/vec.ts';
import { PALETTES } from './colour.ts';
import { fmt } from './shared.ts';

/** The formula mode's default colour function: bands by depth, turned by the final point's angle. */
export const COLOUR_FORMULA = 'n / 8 + 0.25 * sin(6 * atan2(y, x))';

const d = DEFAULT_TILE;
const cos = DEFAULT_COLORING;
const colour = (c: Color, label: string, ui: Pick<InputSpec, 'when' | 'more'> = {}) => ({
  type: 'color' as const,
  label,
  default: toHex(c),
  ...ui,
});
/** The modes that colour by a measure of the run, each with its measure (docs/math.md "Colouring by a measure"). */
const MEASURE_MODES = {
  'final-point': null,
  'edge-distance': 'edge',
  'escape-speed': 'speed',
  'orbit-trap': 'trap',
  formula: 'formula',
} as const satisfies Record<string, Measure | null>;
type MeasureMode = keyof typeof MEASURE_MODES;
const MEASURE_MODE_NAMES = Object.keys(MEASURE_MODES) as MeasureMode[];
const MODES = ['cosine', 'depth-hsv', 'parity', 'image', 'limit-set', ...MEASURE_MODE_NAMES] as const;
type Mode = (typeof MODES)[number];
/** Shown only in these colouring modes (shader-gen/colour.ts reads the field only there). */
const inMode = (...modes: Mode[]): FieldCondition => ({ param: 'mode', is: modes });
/** Limit-set mode paints only the limit set: tile fill, inner area and edges do not apply. */
const TILED = inMode('cosine', 'depth-hsv', 'parity', 'image', ...MEASURE_MODE_NAMES);
/** The modes a cosine palette colours (its presets apply to all of them). */
const PALETTED = inMode('cosine', ...MEASURE_MODE_NAMES);
const isMeasureMode = (mode: Mode): mode is MeasureMode => mode in MEASURE_MODES;
/** The final-point measures, by the name the node shows. */
const COORDINATES = ['argument', 'x', 'y', 'radius'] as const;
/** A depth-hsv setting in [lowest, 1]. */
const hsv = (value: number, lowest: number, label: string, step = 0.01) =>
  ({
    kind: 'number',
    default: value,
    min: lowest,
    max: 1,
    step,
    label,
    when: inMode('depth-hsv'),
  }) as const satisfies ParamSpec;
/**
 * The four palette colours are the "custom" palette's; a named preset replaces all four in one
 * choice (the palette field itself shows only in cosine mode, so they do too).
 */
const CUSTOM: FieldCondition = { param: 'palette', is: ['custom'] };
const PALETTE_CHOICES = [...Object.keys(PALETTES), 'custom'] as const;
const rad = (deg: number) => (deg * Math.PI) / 180;

/** The picture's turn handle: centre + R(θ)(0, size/2), the middle of its top edge. */
const topOf = (c: Vec2, size: number, theta: number): Vec2 => [
  c[0] - Math.sin(theta) * (size / 2),
  c[1] + Math.cos(theta) * (size / 2),
];

export const tileNode = defineNode({
  type: 'tile',
  version: 1,
  label: 'Tile colouring',
  category: 'Colour',
  color: '#b07cf0',
  doc: 'How points are coloured: by depth (HSV, cosine palette, two tones), by the final point, the distance to the tile edge, the escape speed, an orbit trap or a formula of your own (palettes), a picture seen through the kaleidoscope, or only the limit set; plus tile fill, orbit seeds, an inner area, limit-set colour, background and edges.',
  inputs: {
    a: colour(cos.a, 'palette a', { when: CUSTOM }),
    b: colour(cos.b, 'palette b', { when: CUSTOM }),
    c: colour(cos.c, 'palette c', { when: CUSTOM }),
    d: colour(cos.d, 'palette d', { when: CUSTOM }),
    even: colour([0.93, 0.91, 0.85], 'even', { when: inMode('parity') }),
    odd: colour([0.13, 0.16, 0.24], 'odd', { when: inMode('parity') }),
    // The two colours of limit-set mode; in the other modes they are rarely changed.
    limit: colour(d.limitColor, 'limit set', { more: TILED }),
    background: colour(d.background, 'background', { more: TILED }),
    edgeColor: colour(d.edgeColor, 'edge colour', { when: TILED, more: true }),
    fill: colour([0, 0, 0], 'tile fill', { when: { param: 'fillTile', is: [true] } }),
    image: {
      type: 'image',
      label: 'picture',
      optional: true,
      doc: 'picture mode: the picture seen through the kaleidoscope (the built-in checker when unwired)',
      when: inMode('image'),
    },
    imageCenter: { type: 'point', label: 'picture centre', default: [0, 0], when: inMode('image') },
    imageSize: {
      type: 'number',
      label: 'picture height',
      default: 1,
      min: 0,
      step: 0.01,
      when: inMode('image'),
    },
    imageRotation: {
      type: 'number',
      label: 'picture rotation °',
      default: 0,
      step: 1,
      when: inMode('image'),
    },
    seeds: {
      type: 'seed',
      label: 'seeds',
      optional: true,
      doc: 'orbit seeds: each one and all its images are painted',
    },
    trapCenter: { type: 'point', label: 'trap centre', default: [0, 0], when: inMode('orbit-trap') },
    trapRadius: {
      type: 'number',
      label: 'trap radius',
      default: 0.5,
      min: 0,
      step: 0.01,
      doc: 'the trap is this circle (0: a point); each point is coloured by how near its orbit comes to it',
      when: inMode('orbit-trap'),
    },
    inner: {
      type: 'circle',
      label: 'inner area',
      optional: true,
      doc: 'when wired, only points whose final point lies inside this circle keep their colour (Fig. 22)',
      when: TILED,
    },
  },
  outputs: { tile: { type: 'tile', label: 'tile' } },
  params: {
    mode: { kind: 'enum', default: 'cosine', options: MODES, label: 'colouring' },
    palette: {
      kind: 'enum',
      // "custom" by default: documents saved before presets keep their own a, b, c, d.
      default: 'custom',
      options: PALETTE_CHOICES,
      label: 'palette',
      doc: 'a named cosine palette, or "custom" to set a, b, c, d yourself',
      when: PALETTED,
    },
    formula: {
      kind: 'string',
      default: COLOUR_FORMULA,
      maxLength: MAX_FORMULA_LENGTH,
      label: 'colour formula',
      doc: 'formula mode: a formula of the final point z = (x, y), the depth n and the scale s; palette t = offset + scale × it',
      when: inMode('formula'),
    },
    coordinate: {
      kind: 'enum',
      default: 'argument',
      options: COORDINATES,
      label: 'measure',
      doc: 'the final point’s argument (in turns), x, y or distance from the origin',
      when: inMode('final-point'),
    },
    scale: {
      kind: 'number',
      default: 1,
      step: 0.05,
      label: 'palette scale',
      doc: 'palette t = offset + scale × measure',
      when: inMode(...MEASURE_MODE_NAMES),
    },
    offset: {
      kind: 'number',
      default: 0,
      step: 0.01,
      label: 'palette offset',
      doc: 'palette t = offset + scale × measure',
      when: inMode(...MEASURE_MODE_NAMES),
    },
    step: {
      kind: 'number',
      default: cos.step,
      min: 0,
      max: 1,
      step: 0.005,
      label: 'palette step',
      doc: 'palette t = depth × step',
      when: inMode('cosine'),
    },
    hueOffset: hsv(0.01, 0, 'hue start'),
    hueStep: hsv(0.05, -1, 'hue per step', 0.005),
    saturation: hsv(1, 0, 'saturation'),
    value: hsv(1, 0, 'value'),
    glow: {
      kind: 'number',
      default: 0,
      min: 0,
      max: 50,
      step: 0.5,
      label: 'limit glow px',
      doc: 'limit-set mode: a glow about this many pixels wide around the limit set; 0 = none',
      when: inMode('limit-set'),
    },
    fillTile: {
      kind: 'boolean',
      default: false,
      label: 'fill tile',
      doc: 'paint depth 0 (the tile itself) in the tile fill colour',
      when: TILED,
    },
    seedsOnly: {
      kind: 'boolean',
      default: false,
      label: 'seeds only',
      doc: 'points that hit no seed get the background: only the orbits show',
      more: true,
    },
    seedFade: {
      kind: 'number',
      default: 0,
      min: 0,
      max: 1,
      step: 0.01,
      label: 'seed fade',
      doc: 'each step darkens the images of the seeds by this much (0 = all as bright as the seed)',
      more: true,
    },
    edgeWidth: {
      kind: 'number',
      default: d.edgeWidth,
      min: 0,
      max: 20,
      step: 0.5,
      label: 'edge px',
      doc: 'tile edges of constant pixel width; 0 = none',
      when: TILED,
      more: true,
    },
  },
  evaluate: ({ inputs, params, nodeId }) => {
    const c = inputs;
    const mode = params.mode;
    const size = inputs.imageSize;
    if (mode === 'image' && !(size > 0))
      return {
        diagnostics: [
          diag('degenerate', { port: 'imageSize' }, `picture height must be positive, got ${fmt(size)}`),
        ],
      };
    const palette = params.palette === 'custom' ? c : (PALETTES[params.palette] ?? c);
    if (mode === 'formula') {
      const checked = formulaFor(
        nodeId,
        params.formula,
        COLOUR_NAMES,
        ['number'],
        'a colour formula gives a number',
      );
      if ('problem' in checked) return { diagnostics: [checked.problem] };
    }
    const coloring: Coloring = isMeasureMode(mode)
      ? {
          mode: 'measure',
          measure: MEASURE_MODES[mode] ?? params.coordinate,
          a: palette.a,
          b: palette.b,
          c: palette.c,
          d: palette.d,
          scale: params.scale,
          offset: params.offset,
          trap: { c: inputs.trapCenter, r: inputs.trapRadius },
          ...(mode === 'formula' ? { formula: params.formula } : {}),
        }
      : mode === 'cosine'
        ? { mode, a: palette.a, b: palette.b, c: palette.c, d: palette.d, step: params.step }
        : mode === 'parity'
          ? { mode, even: c.even, odd: c.odd }
          : mode === 'image'
            ? {
                mode,
                image: inputs.image ?? BUILTIN_PICTURE,
                center: inputs.imageCenter,
                size,
                rotation: rad(inputs.imageRotation),
              }
            : mode === 'limit-set'
              ? { mode, glow: params.glow }
              : {
                  mode,
                  hueOffset: params.hueOffset,
                  hueStep: params.hueStep,
                  saturation: params.saturation,
                  value: params.value,
                };
    let seeds = inputs.seeds;
    const diagnostics = [];
    if (seeds.length > LIMITS.maxSeeds) {
      diagnostics.push(diag('tooManySeeds', { port: 'seeds' }, seeds.length, LIMITS.maxSeeds));
      seeds = seeds.slice(0, LIMITS.maxSeeds);
    }
    const tile: TileSpec = {
      nodeId,
      coloring,
      limitColor: c.limit,
      background: c.background,
      edgeWidth: params.edgeWidth,
      edgeColor: c.edgeColor,
      fill: params.fillTile ? c.fill : null,
      seeds,
      seedsOnly: seeds.length > 0 && params.seedsOnly,
      seedFade: params.seedFade,
      inner: inputs.inner ?? null,
    };
    const extras = [
      seeds.length > 0 ? `${seeds.length} seed${seeds.length === 1 ? '' : 's'}` : '',
      tile.inner ? 'inner area' : '',
    ].filter(Boolean);
    const shown = [
      mode === 'final-point' ? `${mode} (${params.coordinate})` : mode,
      (mode === 'cosine' || isMeasureMode(mode)) && params.palette !== 'custom' ? params.palette : '',
    ]
      .filter(Boolean)
      .join(' · ');
    return { outputs: { tile }, diagnostics, readout: [shown, ...extras].join(', ') };
  },
  overlay: ({ params, inputs }) =>
    params.mode === 'image'
      ? [{ shape: 'circle', circle: { c: inputs.imageCenter, r: inputs.imageSize / 2 } }]
      : params.mode === 'orbit-trap'
        ? [{ shape: 'circle', circle: { c: inputs.trapCenter, r: inputs.trapRadius } }]
        : [],
  handles: ({ params, inputs }) => {
    if (params.mode === 'orbit-trap') return [{ handle: 'trap-center', at: inputs.trapCenter }];
    if (params.mode !== 'image') return [];
    const c = inputs.imageCenter;
    return [
      { handle: 'picture-center', at: c },
      { handle: 'picture-top', at: topOf(c, inputs.imageSize, rad(inputs.imageRotation)) },
    ];
  },
  /** The centre moves the picture; the top handle scales it (height = 2·distance) and turns it. */
  drag: (handle, to, ctx) => {
    if (handle === 'trap-center') return { trapCenter: [...to] };
    if (handle === 'picture-center') return { imageCenter: [...to] };
    const c = ctx.inputs.imageCenter;
    const turn = Math.atan2(to[1] - c[1], to[0] - c[0]) - Math.PI / 2;
    return { imageSize: Math.max(1e-6, 2 * dist(c, to)), imageRotation: (turn * 180) / Math.PI };
  },
});
