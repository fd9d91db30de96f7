/** Colour values: a picked colour and cosine palettes for the tile's a, b, c, d inputs. */
import { defineNode } from '../core/define-node.ts';
import { toHex } from '../core/port-values.ts';
import { DEFAULT_COLORING } from '../core/tile-spec.ts';
import type { Color } from '../core/values.ts';

export const colorNode = defineNode({
  type: 'color',
  version: 1,
  label: 'Colour',
  category: 'Colour',
  color: '#f08a5d',
  doc: 'A colour from a colour picker, to wire into any colour input.',
  inputs: {},
  outputs: { color: { type: 'color', label: 'colour' } },
  params: { color: { kind: 'color', default: '#e85d75', label: 'colour' } },
  evaluate: ({ params }) => ({
    outputs: { color: params.color },
    readout: toHex(params.color),
  }),
});

type Palette = { readonly a: Color; readonly b: Color; readonly c: Color; readonly d: Color };

const half: Color = [0.5, 0.5, 0.5];
const one: Color = [1, 1, 1];
const cos = DEFAULT_COLORING;

/**
 * Named palettes of the form a + b·cos(2π(c·t + d)) (Quilez's examples whose c fits in [0, 1]);
 * "rainbow" is the tile's default.
 */
export const PALETTES: Readonly<Record<string, Palette>> = {
  rainbow: { a: cos.a, b: cos.b, c: cos.c, d: cos.d },
  warm: { a: half, b: half, c: one, d: [0, 0.1, 0.2] },
  dusk: { a: half, b: half, c: one, d: [0.3, 0.2, 0.2] },
  lime: { a: half, b: half, c: [1, 1, 0.5], d: [0.8, 0.9, 0.3] },
  ember: { a: half, b: half, c: [1, 0.7, 0.4], d: [0, 0.15, 0.2] },
};

/** A palette colour of the "custom" preset (the named presets ignore it, so it is hidden then). */
const colour = (c: Color, label: string, doc: string) => ({
  type: 'color' as const,
  label,
  default: toHex(c),
  doc,
  when: { param: 'preset', is: ['custom'] },
});

export const cosinePaletteNode = defineNode({
  type: 'cosine-palette',
  version: 1,
  label: 'Cosine palette',
  category: 'Colour',
  color: '#f08a5d',
  doc: "The four colours a, b, c, d of a cosine palette a + b·cos(2π(c·t + d)), from a preset or your own, for the tile's palette inputs.",
  inputs: {
    a: colour(cos.a, 'a (centre)', 'used when the preset is "custom"'),
    b: colour(cos.b, 'b (swing)', 'used when the preset is "custom"'),
    c: colour(cos.c, 'c (frequency)', 'used when the preset is "custom"'),
    d: colour(cos.d, 'd (phase)', 'used when the preset is "custom"'),
  },
  outputs: {
    a: { type: 'color', label: 'a' },
    b: { type: 'color', label: 'b' },
    c: { type: 'color', label: 'c' },
    d: { type: 'color', label: 'd' },
  },
  params: {
    preset: {
      kind: 'enum',
      default: 'rainbow',
      options: [...Object.keys(PALETTES), 'custom'],
      label: 'preset',
      doc: '"custom" uses the a, b, c, d inputs',
    },
  },
  evaluate: ({ inputs, params }) => {
    const preset = params.preset;
    const p: Palette = PALETTES[preset] ?? inputs;
    return { outputs: { a: p.a, b: p.b, c: p.c, d: p.d }, readout: preset };
  },
});
