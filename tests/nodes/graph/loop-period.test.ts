import { readFileSync } from 'node:fs';
import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import { docSchema, type GraphDoc } from '../../../nodes/graph/document.ts';
import { evaluateGraph } from '../../../nodes/graph/evaluate.ts';
import { frameTime, loopFrameCount, loopIsFrameExact } from '../../../nodes/graph/frame-times.ts';
import { asFraction, commonPeriod, loopPeriod } from '../../../nodes/graph/loop-period.ts';
import { registry } from '../../../nodes/types/index.ts';
import { doc, edge, node } from '../support/doc.ts';

const period = (g: GraphDoc) => loopPeriod(g, evaluateGraph(g, registry));

describe('asFraction / commonPeriod', () => {
  it('reads decimal periods as exact fractions', () => {
    expect(asFraction(2.5)).toEqual({ num: 5, den: 2 });
    expect(asFraction(1 / 3)).toEqual({ num: 1, den: 3 });
    expect(asFraction(10)).toEqual({ num: 10, den: 1 });
    expect(asFraction(Math.PI)).toBeNull(); // no fraction with a small denominator is that close
    expect(asFraction(0)).toBeNull();
  });

  it('is the least common multiple of rational periods', () => {
    expect(commonPeriod([4, 6])).toBe(12);
    expect(commonPeriod([2.5, 1.5])).toBeCloseTo(7.5, 12);
    expect(commonPeriod([1 / 3, 0.5])).toBeCloseTo(1, 12);
    expect(commonPeriod([4, Math.PI])).toBeNull();
    expect(commonPeriod([997, 991])).toBeNull(); // 988027 s: no loop worth recording
  });

  it('is a whole number of every period, and the least such (property)', () => {
    const period = fc
      .tuple(fc.integer({ min: 1, max: 60 }), fc.constantFrom(1, 2, 3, 4, 5, 10))
      .map(([n, d]) => n / d);
    fc.assert(
      fc.property(fc.array(period, { minLength: 1, maxLength: 3 }), (ps) => {
        const L = commonPeriod(ps);
        if (L === null) return; // beyond MAX_LOOP_SECONDS
        const whole = (x: number) => Math.abs(x - Math.round(x)) < 1e-9;
        expect(ps.every((p) => whole(L / p))).toBe(true);
        // L/k for a prime k is never a common multiple too (else L would not be the least).
        for (const k of [2, 3, 5, 7]) expect(ps.every((p) => whole(L / k / p))).toBe(false);
      }),
      { seed: 42, numRuns: 300 },
    );
  });
});

describe('loopPeriod', () => {
  it('a graph without time is static', () => {
    expect(period(doc([node('s', 'sine', { period: 3 })]))).toEqual({ kind: 'static' });
  });

  it('one cycle: its period divided by the speed of its clock', () => {
    const g = doc(
      [node('t', 'time', { speed: 2 }), node('m', 'circular-motion', { period: 10 })],
      [edge('e', 't.time', 'm.t')],
    );
    expect(period(g)).toMatchObject({ kind: 'loop', seconds: 5 });
  });

  it('several cycles meet after the LCM of their periods; a stopped clock does not count', () => {
    const g = doc(
      [
        node('t', 'time'),
        node('a', 'sine', { period: 4 }),
        node('b', 'circular-motion', { period: 6 }),
        node('z', 'time', { speed: 0 }),
        node('c', 'sine', { period: 7 }),
      ],
      [edge('e1', 't.time', 'a.t'), edge('e2', 't.time', 'b.t'), edge('e3', 'z.time', 'c.t')],
    );
    const p = period(g);
    expect(p).toMatchObject({ kind: 'loop', seconds: 12 });
    // …and the graph really repeats: the circular motion's point is the same at t and t + 12.
    const at = (time: number) => evaluateGraph(g, registry, { time }).nodes.get('b')!.outputs!.point;
    const [x0, y0] = at(1.3) as number[];
    const [x1, y1] = at(13.3) as number[];
    expect(x1).toBeCloseTo(x0, 10);
    expect(y1).toBeCloseTo(y0, 10);
  });

  it('incommensurable periods: no common loop, said with the periods', () => {
    const g = doc(
      [node('t', 'time'), node('a', 'sine', { period: 1 }), node('b', 'sine', { period: Math.SQRT2 })],
      [edge('e1', 't.time', 'a.t'), edge('e2', 't.time', 'b.t')],
    );
    const p = period(g);
    expect(p.kind).toBe('none');
    expect(p.kind === 'none' && p.reason).toMatch(/no common loop.*1\.41421 s/);
  });

  it('time used directly never repeats, and the node is named', () => {
    const g = doc([node('t', 'time'), node('r', 'rotation', {})], [edge('e', 't.time', 'r.angle')]);
    expect(period(g)).toMatchObject({ kind: 'none', nodeId: 'r' });
    const wiredPeriod = doc(
      [node('t', 'time'), node('a', 'sine', {})],
      [edge('e1', 't.time', 'a.t'), edge('e2', 't.time', 'a.period')],
    );
    expect(period(wiredPeriod)).toMatchObject({ kind: 'none', nodeId: 'a' });
  });

  it('a formula that reads the time t never repeats (it is not static), and the node is named', () => {
    const shape = node('s', 'seed-shape', { formula: 'length(z) - 0.2 * (1 + 0.3 * sin(t))' });
    const p = period(doc([shape]));
    expect(p).toMatchObject({ kind: 'none', nodeId: 's' });
    expect(p.kind === 'none' && p.reason).toMatch(/reads the time t in its formula.*Sine wave/);
    // t as a letter inside another name, or a formula without t, is no clock
    expect(period(doc([node('f', 'formula', { formula: 'sqrt(a) + tan(b)' })]))).toEqual({ kind: 'static' });
    // a formula that does not parse is the node's own error, not a clock
    expect(period(doc([node('f', 'formula', { formula: 't +' })]))).toEqual({ kind: 'static' });
  });

  it('the animated example loops every 10 s', () => {
    const text = readFileSync('examples/animated-breathing-loxodromic.kleinflow.json', 'utf8');
    const g = docSchema.parse(JSON.parse(text));
    expect(period(g)).toMatchObject({ kind: 'loop', seconds: 10 });
  });
});

describe('frame times', () => {
  it('frame i is at i/fps exactly, however far in', () => {
    expect(frameTime(0, 30)).toBe(0);
    expect(frameTime(3000, 30)).toBe(100);
    expect(frameTime(7, 24)).toBe(7 / 24);
  });

  it('one loop: round(L·fps) frames, the next one being frame 0 again', () => {
    expect(loopFrameCount(10, 24)).toBe(240);
    expect(frameTime(loopFrameCount(10, 24), 24)).toBe(10);
    expect(loopIsFrameExact(10, 24)).toBe(true);
    expect(loopIsFrameExact(7.5, 25)).toBe(false);
    expect(loopFrameCount(0.01, 10)).toBe(1);
  });
});
