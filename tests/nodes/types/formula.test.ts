import { describe, expect, it } from 'vitest';
import { evaluateGraph } from '../../../nodes/graph/evaluate.ts';
import { registry } from '../../../nodes/types/index.ts';
import { doc, edge, node } from '../support/doc.ts';
import { codes, evalNode } from '../support/eval-node.ts';

describe('formula node', () => {
  it('gives a number on its number output and leaves the point output empty', () => {
    const r = evalNode('formula');
    expect(r.outputs).toEqual({ value: 3 });
    expect(r.readout).toBe('3');
    expect(evalNode('formula', { formula: 'sqrt(a*a + b*b)', a: 3, b: 4 }).outputs!.value).toBe(5);
  });

  it('gives a point on its point output', () => {
    const r = evalNode('formula', { formula: 'mix(p, q, 0.5) + point(0, c)', q: [2, 0], c: 1 });
    expect(r.outputs).toEqual({ point: [1, 1] });
    expect(r.readout).toBe('(1, 1)');
  });

  it('follows the animation time t', () => {
    expect(evalNode('formula', { formula: '2 * t' }, 1.25).outputs!.value).toBe(2.5);
  });

  it('names the characters at fault in a KF327 error and computes nothing', () => {
    const r = evalNode('formula', { formula: 'a + sin(p)' });
    expect(codes(r)).toEqual(['KF327']);
    expect(r.diagnostics[0]!.message).toBe(
      'formula, characters 5–10 (“sin(p)”): sin takes sin(number), not (point)',
    );
    expect(r.outputs ?? {}).toEqual({});
    expect(evalNode('formula', { formula: 'a +' }).diagnostics[0]!.message).toContain('at the end');
    expect(evalNode('formula', { formula: 'a < b' }).diagnostics[0]!.message).toContain('comparison');
  });

  it('says so when the result is not finite', () => {
    expect(codes(evalNode('formula', { formula: '1 / (a - 1)' }))).toEqual(['KF303']);
    expect(codes(evalNode('formula', { formula: 'p / 0' }))).toEqual(['KF303']);
  });

  it('drives other nodes: a circle whose radius is a formula of a wired number', () => {
    const ev = evaluateGraph(
      doc(
        [
          node('n', 'number', { value: 4 }),
          node('f', 'formula', { formula: 'sqrt(a) / 2' }),
          node('c', 'circle'),
        ],
        [edge('e1', 'n.value', 'f.a'), edge('e2', 'f.value', 'c.radius')],
      ),
      registry,
    );
    expect(ev.nodes.get('c')!.outputs!.circle).toMatchObject({ r: 1 });
  });

  it('an input wired to the output the formula leaves empty says why', () => {
    const ev = evaluateGraph(
      doc(
        [node('f', 'formula', { formula: 'a * 2' }), node('c', 'circle')],
        [edge('e1', 'f.point', 'c.center')],
      ),
      registry,
    );
    expect(ev.nodes.get('c')!.diagnostics.length).toBeGreaterThan(0);
  });
});
