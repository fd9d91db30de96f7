import { defineNode } from '../core/define-node.ts';
import { toHex } from '../core/port-values.ts';
import { type Coloring, DEFAULT_TILE, type TileSpec } from '../core/scene.ts';
import type { Color } from '../core/values.ts';

const d = DEFAULT_TILE;
const cos = d.coloring as Extract<Coloring, { mode: 'cosine' }>;
const colour = (c: Color, label: string) => ({ type: 'color' as const, label, default: toHex(c) });

export const tileNode = defineNode({
  type: 'tile',
  version: 1,
  label: 'Tile colouring',
  category: 'Colour',
  color: '#b07cf0',
  doc: 'How points are coloured by their depth: HSV hues, a cosine palette or two tones; plus limit-set colour, background and edges.',
  inputs: {
    a: colour(cos.a, 'palette a'),
    b: colour(cos.b, 'palette b'),
    c: colour(cos.c, 'palette c'),
    d: colour(cos.d, 'palette d'),
    even: colour([0.93, 0.91, 0.85], 'even'),
    odd: colour([0.13, 0.16, 0.24], 'odd'),
    limit: colour(d.limitColor, 'limit set'),
    background: colour(d.background, 'background'),
    edgeColor: colour(d.edgeColor, 'edge colour'),
  },
  outputs: { tile: { type: 'tile', label: 'tile' } },
  params: {
    mode: { kind: 'enum', default: 'cosine', options: ['cosine', 'depth-hsv', 'parity'], label: 'colouring' },
    step: {
      kind: 'number',
      default: cos.step,
      min: 0,
      max: 1,
      step: 0.005,
      label: 'palette step',
      doc: 'palette t = depth × step',
    },
    hueOffset: { kind: 'number', default: 0.01, min: 0, max: 1, step: 0.01, label: 'hue start' },
    hueStep: { kind: 'number', default: 0.05, min: -1, max: 1, step: 0.005, label: 'hue per step' },
    saturation: { kind: 'number', default: 1, min: 0, max: 1, step: 0.01, label: 'saturation' },
    value: { kind: 'number', default: 1, min: 0, max: 1, step: 0.01, label: 'value' },
    edgeWidth: {
      kind: 'number',
      default: d.edgeWidth,
      min: 0,
      max: 20,
      step: 0.5,
      label: 'edge px',
      doc: 'tile edges of constant pixel width; 0 = none',
    },
  },
  evaluate: ({ inputs, params, nodeId }) => {
    const c = (k: string) => inputs[k] as Color;
    const mode = params.mode as Coloring['mode'];
    const coloring: Coloring =
      mode === 'cosine'
        ? { mode, a: c('a'), b: c('b'), c: c('c'), d: c('d'), step: params.step as number }
        : mode === 'parity'
          ? { mode, even: c('even'), odd: c('odd') }
          : {
              mode,
              hueOffset: params.hueOffset as number,
              hueStep: params.hueStep as number,
              saturation: params.saturation as number,
              value: params.value as number,
            };
    const tile: TileSpec = {
      nodeId,
      coloring,
      limitColor: c('limit'),
      background: c('background'),
      edgeWidth: params.edgeWidth as number,
      edgeColor: c('edgeColor'),
    };
    return { outputs: { tile }, readout: mode };
  },
});
