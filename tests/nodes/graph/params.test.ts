import { describe, expect, it } from 'vitest';
import { defineNode } from '../../../nodes/core/define-node.ts';
import { evaluateGraph } from '../../../nodes/graph/evaluate.ts';
import { checkNumber, resolveParams } from '../../../nodes/graph/params.ts';
import { registry } from '../../../nodes/types/index.ts';
import { doc, node } from '../support/doc.ts';

/** A node type with one input of every inline-editable port type and one param of every kind. */
const everything = defineNode({
  type: 'everything',
  version: 1,
  label: 'Everything',
  category: 'Values',
  color: '#123456',
  doc: 'test node',
  inputs: {
    n: { type: 'number', default: 2, min: 1, max: 10, integer: true },
    free: { type: 'number', default: 0.5 },
    pt: { type: 'point', default: [1, 2] },
    ln: { type: 'line', default: { a: [0, 0], b: [1, 0] } },
    circ: { type: 'circle', default: { c: [0, 0], r: 1 } },
    col: { type: 'color', default: '#ff0000' },
    img: { type: 'image', default: { src: 'data:x', width: 2, height: 3 } },
    els: { type: 'element', optional: true },
    tile: { type: 'tile', optional: true },
    wired: { type: 'point', optional: true },
  },
  outputs: {},
  params: {
    flag: { kind: 'boolean', default: true },
    mode: { kind: 'enum', default: 'a', options: ['a', 'b'] },
    count: { kind: 'number', default: 3, min: 0, max: 5, integer: true },
    tint: { kind: 'color', default: '#0080ff' },
    text: { kind: 'string', default: 'hi' },
  },
  evaluate: () => ({ outputs: {} }),
});

const resolve = (params: Record<string, unknown>, connected: string[] = []) =>
  resolveParams(everything, { id: 'x', params }, new Set(connected), ['nodes', 3]);

describe('resolveParams', () => {
  it('fills every default and converts colours to [r, g, b]', () => {
    const r = resolve({});
    expect(r.diagnostics).toEqual([]);
    expect(r.inline).toEqual({
      n: 2,
      free: 0.5,
      pt: [1, 2],
      ln: { a: [0, 0], b: [1, 0] },
      circ: { c: [0, 0], r: 1 },
      col: [1, 0, 0],
      img: { src: 'data:x', width: 2, height: 3 },
    });
    expect(r.params).toEqual({ flag: true, mode: 'a', count: 3, tint: [0, 128 / 255, 1], text: 'hi' });
  });

  it('takes given values over defaults', () => {
    const r = resolve({ n: 7, pt: [-3, 4], col: '#00FF00', flag: false, mode: 'b', count: 0, text: '' });
    expect(r.diagnostics).toEqual([]);
    expect(r.inline.n).toBe(7);
    expect(r.inline.pt).toEqual([-3, 4]);
    expect(r.inline.col).toEqual([0, 1, 0]);
    expect(r.params).toMatchObject({ flag: false, mode: 'b', count: 0, text: '' });
  });

  const bad: [string, unknown, RegExp][] = [
    ['n', 0, /≥ 1/],
    ['n', 11, /≤ 10/],
    ['n', 2.5, /integer/],
    ['n', 'two', /number value/],
    ['free', Number.NaN, /number value/],
    ['pt', [1], /point value/],
    ['pt', [1, Number.POSITIVE_INFINITY], /point value/],
    ['ln', { a: [0, 0] }, /line value/],
    ['circ', { c: [0, 0], r: 'big' }, /circle value/],
    ['col', 'red', /color value/],
    ['col', '#12345', /color value/],
    ['img', { src: 1 }, /image value/],
    ['flag', 'yes', /true or false/],
    ['mode', 'c', /one of "a", "b"/],
    ['count', 6, /≤ 5/],
    ['count', -1, /≥ 0/],
    ['count', 1.5, /integer/],
    ['count', '3', /expected a number/],
    ['count', Number.NaN, /finite/],
    ['tint', '#GGGGGG', /colour like/],
    ['text', 42, /expected text/],
    ['text', 'x'.repeat(10_001), /at most 10000/],
  ];
  it.each(bad)('KF301: %s = %j is rejected with its path', (name, value, why) => {
    const r = resolve({ [name]: value });
    expect(r.diagnostics).toHaveLength(1);
    const [d] = r.diagnostics;
    expect(d).toMatchObject({ code: 'KF301', severity: 'error', nodeId: 'x', port: name });
    expect(d.path).toBe(`nodes[3].params.${name}`);
    expect(d.message.startsWith(`${name}: `)).toBe(true);
    expect(d.message).toMatch(why);
    expect(name in r.inline || name in r.params).toBe(false);
  });

  it('ignores the inline value of a connected input (kept in the document)', () => {
    const r = resolve({ pt: 'garbage' }, ['pt']);
    expect(r.diagnostics).toEqual([]);
    expect('pt' in r.inline).toBe(false);
  });

  it('element and tile inputs and inputs without default have no inline value', () => {
    const r = resolve({});
    for (const k of ['els', 'tile', 'wired']) expect(k in r.inline).toBe(false);
  });

  it('an unknown param is a warning that names it, and is kept', () => {
    const params = { speed: 3 };
    const r = resolve(params);
    expect(r.diagnostics).toEqual([
      expect.objectContaining({ code: 'KF301', severity: 'warning', path: 'nodes[3].params.speed' }),
    ]);
    expect(r.diagnostics[0].message).toContain('"everything" has no parameter "speed"');
    expect(params).toEqual({ speed: 3 });
  });

  it('quotes odd param names in paths', () => {
    const r = resolve({ 'my param': 1 });
    expect(r.diagnostics[0].path).toBe('nodes[3].params["my param"]');
  });

  it('reports all problems at once', () => {
    const r = resolve({ n: 0, mode: 'z', extra: 1 });
    expect(r.diagnostics.map((d) => [d.port ?? null, d.severity])).toEqual([
      ['n', 'error'],
      ['mode', 'error'],
      [null, 'warning'],
    ]);
  });
});

describe('checkNumber', () => {
  it('checks finiteness, integrality and bounds', () => {
    expect(checkNumber({}, 5)).toBeNull();
    expect(checkNumber({ min: 0, max: 1 }, 0)).toBeNull();
    expect(checkNumber({ min: 0, max: 1 }, 1)).toBeNull();
    expect(checkNumber({ min: 0 }, -1e-9)).toMatch(/≥ 0/);
    expect(checkNumber({}, Number.POSITIVE_INFINITY)).toMatch(/finite/);
    expect(checkNumber({ integer: true }, 3)).toBeNull();
  });
});

describe('params through evaluation', () => {
  it('a bad radius is reported as nodes[i].params.radius and the node has no output', () => {
    const d = doc([
      node('a', 'point'),
      node('b', 'point'),
      node('r', 'render'),
      node('c', 'circle', { radius: -1 }),
    ]);
    const ev = evaluateGraph(d, registry);
    const bad = ev.diagnostics.find((x) => x.code === 'KF301')!;
    expect(bad).toMatchObject({ path: 'nodes[3].params.radius', nodeId: 'c', port: 'radius' });
    expect(bad.message).toBe('radius: expected a number ≥ 0, got -1');
    expect(ev.nodes.get('c')?.outputs).toBeUndefined();
  });
});
