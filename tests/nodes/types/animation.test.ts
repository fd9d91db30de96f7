import { describe, expect, it } from 'vitest';
import { evaluateGraph } from '../../../nodes/graph/evaluate.ts';
import { registry } from '../../../nodes/types/index.ts';
import { compile } from '../../../shader-gen/compile.ts';
import { doc, edge, node } from '../support/doc.ts';
import { checkDefaults, codes, defOf, evalNode } from '../support/eval-node.ts';

describe('animation nodes', () => {
  it('time = seconds × speed', () => {
    expect(checkDefaults('time').outputs!.time).toBe(0);
    expect(evalNode('time', { speed: 2 }, 1.5).outputs!.time).toBe(3);
  });

  it('sine: offset + amplitude·sin(2π t/period + phase)', () => {
    checkDefaults('sine');
    const v = (t: number) =>
      evalNode('sine', { t, period: 2, amplitude: 3, phase: 0, offset: 1 }).outputs!.value as number;
    expect(v(0)).toBeCloseTo(1, 14);
    expect(v(0.5)).toBeCloseTo(4, 14); // a quarter period: the crest
    expect(v(1.5)).toBeCloseTo(-2, 14);
    expect(evalNode('sine', { phase: Math.PI / 2 }).outputs!.value).toBeCloseTo(1, 14);
    expect(codes(evalNode('sine', { period: 0 }))).toEqual(['KF303']);
  });

  it('circular motion goes round once per period; dragging the point sets radius and phase', () => {
    checkDefaults('circular-motion');
    const at = (t: number) =>
      evalNode('circular-motion', { center: [1, 1], radius: 2, period: 4, t }).outputs!.point as number[];
    expect(at(0)[0]).toBeCloseTo(3, 14);
    expect(at(1)[1]).toBeCloseTo(3, 14);
    expect(at(4)[0]).toBeCloseTo(3, 12);
    const def = defOf('circular-motion');
    const r = evalNode('circular-motion', { center: [0, 0], period: 4, t: 1 });
    const d = def.drag!('point', [0, -3], r.ctx!);
    expect(d.radius).toBeCloseTo(3, 14);
    const again = evalNode('circular-motion', {
      center: [0, 0],
      period: 4,
      t: 1,
      radius: d.radius,
      phase: d.phase,
    });
    const p = again.outputs!.point as number[];
    expect(p[0]).toBeCloseTo(0, 12);
    expect(p[1]).toBeCloseTo(-3, 12);
  });

  it('a wired time drives the sine through the graph', () => {
    const g = doc([node('t', 'time'), node('s', 'sine', { period: 4 })], [edge('e', 't.time', 's.t')]);
    const at = (time: number) =>
      evaluateGraph(g, registry, { time }).nodes.get('s')!.outputs!.value as number;
    expect(at(0)).toBeCloseTo(0, 14);
    expect(at(1)).toBeCloseTo(1, 14);
  });

  it('animating moves values only: the same source (so the same program), new uniforms', () => {
    const g = doc(
      [
        node('t', 'time'),
        node('orbit', 'circular-motion', { radius: 0.4, period: 3 }),
        node('c', 'circle', { radius: 0.5 }),
        node('inv', 'inversion'),
        node('w', 'sine', { period: 5, amplitude: 10, offset: 15 }),
        node('sp', 'spiral-similarity', { r1: 0.3, r2: 0.45 }),
        node('out', 'render'),
      ],
      [
        edge('e1', 't.time', 'orbit.t'),
        edge('e2', 'orbit.point', 'c.center'),
        edge('e3', 'c.circle', 'inv.circle'),
        edge('e4', 't.time', 'w.t'),
        edge('e5', 'w.value', 'sp.angle'),
        edge('e6', 'inv.element', 'out.elements'),
        edge('e7', 'sp.element', 'out.elements'),
      ],
    );
    const at = (time: number) => compile(evaluateGraph(g, registry, { time }).scene);
    const a = at(0);
    const b = at(1.3);
    expect(b.source).toBe(a.source);
    expect(JSON.stringify(b.uniforms)).not.toBe(JSON.stringify(a.uniforms));
  });
});
