import { describe, expect, it } from 'vitest';
import { defineNode } from '../../../nodes/core/define-node.ts';
import { controllingParams, isFieldInMore, isFieldShown } from '../../../nodes/core/field-visibility.ts';
import { cosinePaletteNode } from '../../../nodes/types/colour.ts';
import { tileNode } from '../../../nodes/types/tile.ts';

/** A made-up node: a shape enum, a toggle that only matters for disks, and fields hanging off both. */
const demo = defineNode({
  type: 'demo',
  version: 1,
  label: 'Demo',
  category: 'Values',
  color: '#123456',
  doc: 'test node',
  inputs: {
    radius: { type: 'number', label: 'radius', default: 1, when: { param: 'shape', is: ['disk'] } },
    side: { type: 'number', label: 'side', default: 1, when: { param: 'shape', is: ['square', 'cube'] } },
    rim: { type: 'color', label: 'rim', default: '#ffffff', when: { param: 'outlined', is: [true] } },
    always: { type: 'number', label: 'always', default: 0, more: true },
    sometimes: { type: 'number', label: 'sometimes', default: 0, more: { param: 'shape', is: ['disk'] } },
  },
  outputs: { out: { type: 'number', label: 'out' } },
  params: {
    shape: { kind: 'enum', default: 'disk', options: ['disk', 'square', 'cube'], label: 'shape' },
    outlined: { kind: 'boolean', default: false, label: 'outlined', when: { param: 'shape', is: ['disk'] } },
    plain: { kind: 'number', default: 0, label: 'plain' },
  },
  evaluate: () => ({ outputs: { out: 0 } }),
});

const shown = (params: Record<string, unknown>, connected: Iterable<string> = []) =>
  [...Object.keys(demo.inputs), ...Object.keys(demo.params)].filter((f) =>
    isFieldShown(demo, f, params, new Set(connected)),
  );

describe('isFieldShown', () => {
  it('shows a field while its enum param has one of the listed values', () => {
    expect(shown({ shape: 'disk' })).toEqual(['radius', 'always', 'sometimes', 'shape', 'outlined', 'plain']);
    expect(shown({ shape: 'cube' })).toEqual(['side', 'always', 'sometimes', 'shape', 'plain']);
  });

  it('uses the default for a missing or invalid controlling value', () => {
    expect(shown({})).toEqual(shown({ shape: 'disk' }));
    expect(shown({ shape: 'hexagon', outlined: 'yes' })).toEqual(shown({ shape: 'disk', outlined: false }));
  });

  it('follows a toggle, and hides what a hidden toggle controls', () => {
    expect(isFieldShown(demo, 'rim', { outlined: true })).toBe(true);
    expect(isFieldShown(demo, 'rim', { outlined: false })).toBe(false);
    // outlined is kept true in the document, but it means nothing for a square: so does the rim
    expect(isFieldShown(demo, 'rim', { shape: 'square', outlined: true })).toBe(false);
  });

  it('always shows a wired input, and only inputs count as wired', () => {
    expect(isFieldShown(demo, 'radius', { shape: 'cube' }, new Set(['radius']))).toBe(true);
    expect(isFieldShown(demo, 'outlined', { shape: 'cube' }, new Set(['outlined']))).toBe(false);
  });

  it('knows nothing of names the node does not declare', () => {
    expect(isFieldShown(demo, 'nope', {})).toBe(false);
    expect(isFieldShown(demo, 'toString', {})).toBe(false);
  });

  it('never edits the params it reads', () => {
    const params = Object.freeze({ shape: 'cube', radius: 3 });
    shown(params);
    expect(params).toEqual({ shape: 'cube', radius: 3 });
  });
});

describe('isFieldInMore and controllingParams', () => {
  it('puts "more" fields in the More section, conditionally when the condition says so', () => {
    expect(isFieldInMore(demo, 'always', {})).toBe(true);
    expect(isFieldInMore(demo, 'sometimes', { shape: 'disk' })).toBe(true);
    expect(isFieldInMore(demo, 'sometimes', { shape: 'cube' })).toBe(false);
    expect(isFieldInMore(demo, 'always', {}, new Set(['always']))).toBe(false); // a wire stays in sight
    expect(isFieldInMore(demo, 'plain', {})).toBe(false);
  });

  it('lists the params other fields depend on, in declaration order', () => {
    expect(controllingParams(demo)).toEqual(['shape', 'outlined']);
  });
});

describe('the tile node shows what its colouring mode uses', () => {
  const MODE_FIELDS: Record<string, string[]> = {
    cosine: ['a', 'b', 'c', 'd', 'step'],
    'depth-hsv': ['hueOffset', 'hueStep', 'saturation', 'value'],
    parity: ['even', 'odd'],
    image: ['image', 'imageCenter', 'imageSize', 'imageRotation'],
    'limit-set': ['glow'],
  };
  const modeOnly = Object.values(MODE_FIELDS).flat();

  it.each(Object.keys(MODE_FIELDS))('mode %s', (mode) => {
    const visible = (f: string) => isFieldShown(tileNode, f, { mode });
    for (const f of modeOnly) expect(visible(f), f).toBe(MODE_FIELDS[mode].includes(f));
    for (const f of ['mode', 'limit', 'background', 'seeds', 'seedsOnly', 'seedFade'])
      expect(visible(f), f).toBe(true);
    // limit-set mode paints only the limit set: fill, inner area and edges have no effect there
    const tiled = mode !== 'limit-set';
    for (const f of ['fillTile', 'inner', 'edgeWidth', 'edgeColor']) expect(visible(f), f).toBe(tiled);
    // the limit and background colours are limit-set mode's own, elsewhere rarely changed
    expect(isFieldInMore(tileNode, 'limit', { mode })).toBe(tiled);
    expect(isFieldInMore(tileNode, 'background', { mode })).toBe(tiled);
  });

  it('shows the fill colour only while "fill tile" is on (and means something)', () => {
    expect(isFieldShown(tileNode, 'fill', {})).toBe(false);
    expect(isFieldShown(tileNode, 'fill', { fillTile: true })).toBe(true);
    expect(isFieldShown(tileNode, 'fill', { fillTile: true, mode: 'limit-set' })).toBe(false);
  });

  it('keeps the default set-up short', () => {
    const all = [...Object.keys(tileNode.inputs), ...Object.keys(tileNode.params)];
    const main = all.filter((f) => isFieldShown(tileNode, f, {}) && !isFieldInMore(tileNode, f, {}));
    expect(all.length).toBeGreaterThan(20);
    expect(main.length).toBeLessThanOrEqual(10);
  });

  it('shows the cosine palette colours only for the custom preset', () => {
    expect(isFieldShown(cosinePaletteNode, 'a', {})).toBe(false);
    expect(isFieldShown(cosinePaletteNode, 'a', { preset: 'custom' })).toBe(true);
    expect(isFieldShown(cosinePaletteNode, 'a', { preset: 'warm' }, new Set(['a']))).toBe(true);
  });
});
