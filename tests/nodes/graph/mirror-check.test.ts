import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import type { Diagnostic } from '../../../nodes/core/diagnostics.ts';
import type { Vec2 } from '../../../nodes/core/values.ts';
import type { GraphDoc } from '../../../nodes/graph/document.ts';
import { evaluateGraph } from '../../../nodes/graph/evaluate.ts';
import { formatPiOver } from '../../../nodes/graph/mirror-check.ts';
import { registry } from '../../../nodes/types/index.ts';
import { EQUILATERAL, triangleDoc } from './mirror-fixtures.ts';

const SEED = { seed: 42, numRuns: 60 } as const;
const mirrorWarnings = (d: GraphDoc) =>
  evaluateGraph(d, registry).diagnostics.filter((x) => x.code === 'KF406' || x.code === 'KF407');

/** Applies a diagnostic's fix the way the editor does for params and Line-node handle moves. */
function applyFix(d: GraphDoc, fix: NonNullable<Diagnostic['fix']>): GraphDoc {
  const ev = evaluateGraph(d, registry);
  const patches = new Map<string, Record<string, unknown>>();
  const patch = (id: string, params: Record<string, unknown>) =>
    patches.set(id, { ...(patches.get(id) ?? {}), ...params });
  for (const p of fix.params ?? []) patch(p.nodeId, p.params);
  for (const m of fix.moves ?? []) {
    // A Line node's handle a/b is wired from a point node here: move that point (as a drag does).
    const edge = ev.analysis.incoming.get(m.nodeId)?.get(m.handle)?.[0];
    if (edge) patch(edge.from.node, { x: m.to[0], y: m.to[1] });
    else patch(m.nodeId, { [m.handle]: [...m.to] });
  }
  return {
    ...d,
    nodes: d.nodes.map((n) =>
      patches.has(n.id) ? { ...n, params: { ...n.params, ...patches.get(n.id) } } : n,
    ),
  };
}

describe('mirror check (KF406 kept sides, KF407 angles)', () => {
  it('the anticlockwise *333 triangle has no warning', () => {
    expect(mirrorWarnings(triangleDoc(EQUILATERAL, ['AB', 'BC', 'CA']))).toEqual([]);
  });

  it('AB, AC, BC: names AC, and flipping it gives a clean picture', () => {
    const d = triangleDoc(EQUILATERAL, ['AB', 'AC', 'BC']);
    const [w, ...rest] = mirrorWarnings(d);
    expect(rest).toEqual([]);
    expect(w.code).toBe('KF406');
    expect(w.nodeId).toBe('mAC');
    expect(w.message).toContain('“AC” keeps the wrong side');
    expect(w.fix).toEqual({ label: 'Flip “AC”', params: [{ nodeId: 'mAC', params: { flip: true } }] });
    expect(mirrorWarnings(applyFix(d, w.fix!))).toEqual([]);
  });

  it('a clockwise triangle keeps nothing: all three are named and flipping them fixes it', () => {
    const cw: Vec2[] = [EQUILATERAL[0], EQUILATERAL[2], EQUILATERAL[1]];
    const d = triangleDoc(cw, ['AB', 'BC', 'CA']);
    const ws = mirrorWarnings(d);
    expect(ws.map((w) => w.nodeId)).toEqual(['mAB', 'mBC', 'mCA']);
    expect(ws[0].message).toContain('no common region');
    expect(mirrorWarnings(applyFix(d, ws[0].fix!))).toEqual([]);
  });

  it('a corner that is not π/n shows π/x, and one snap makes the whole triangle exact', () => {
    const d = triangleDoc(
      [
        [0, 0],
        [2, 0],
        [0.6, 1.3],
      ],
      ['AB', 'BC', 'CA'],
    );
    const ws = mirrorWarnings(d);
    expect(ws.length).toBeGreaterThan(0);
    const w = ws[0];
    expect(w.code).toBe('KF407');
    expect(w.message).toMatch(/at π\/\d+\.\d+ \(\d+\.\d°\), not π\/n/);
    expect(w.message).toMatch(/the nearest tiling triangle is \(\d, \d, \d\), π\/\d here/);
    expect(w.fix?.label).toMatch(/^Snap to \(\d, \d, \d\): moves “[ABC]” to \(-?[\d.]+, -?[\d.]+\)$/);
    // Every corner's warning offers the same fix, and after it no angle warning is left.
    expect(new Set(ws.map((x) => x.fix?.label)).size).toBe(1);
    expect(mirrorWarnings(applyFix(d, w.fix!))).toEqual([]);
  });

  it('issue #23: C lifted off √3 snaps back in one click, keeping A and B and the right angle', () => {
    const d = triangleDoc(
      [
        [0, 0],
        [1, 0],
        [0, 1.5],
      ],
      ['AB', 'AC', 'BC'],
      ['AC'],
    );
    const ws = mirrorWarnings(d);
    expect(ws.map((x) => x.code)).toEqual(['KF407', 'KF407']);
    expect(ws[0].fix?.label).toBe('Snap to (2, 3, 6): moves “C” to (0, 1.732)');
    expect(ws[1].fix).toEqual(ws[0].fix);
    expect(ws[0].fix?.moves).toHaveLength(1);
    const after = applyFix(d, ws[0].fix!);
    expect(mirrorWarnings(after)).toEqual([]);
    const at = (id: string) => after.nodes.find((n) => n.id === id)!.params;
    expect(at('A')).toEqual({ x: 0, y: 0 });
    expect(at('B')).toEqual({ x: 1, y: 0 });
    expect(at('C').x).toBeCloseTo(0, 12);
    expect(at('C').y).toBeCloseTo(Math.sqrt(3), 12);
  });

  it('formats angles as π/x with degrees', () => {
    expect(formatPiOver(Math.PI / 3)).toBe('π/3 (60.0°)');
    expect(formatPiOver(Math.PI / 2.5)).toBe('π/2.5 (72.0°)');
  });

  it('property: any triangle wired in any order gets a flip fix or none, then one snap leaves no warning', () => {
    const coord = fc.double({ min: -3, max: 3, noNaN: true });
    const orders = [
      ['AB', 'BC', 'CA'],
      ['AB', 'AC', 'BC'],
      ['BA', 'CB', 'AC'],
      ['BA', 'AC', 'CB'],
    ];
    fc.assert(
      fc.property(
        fc.array(fc.tuple(coord, coord), { minLength: 3, maxLength: 3 }),
        fc.constantFrom(...orders),
        (corners, order) => {
          const [a, b, c] = corners as Vec2[];
          const area = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
          fc.pre(Math.abs(area) > 0.5);
          let d = triangleDoc(corners as Vec2[], order);
          const kept = mirrorWarnings(d).filter((w) => w.code === 'KF406');
          if (kept.length > 0) d = applyFix(d, kept[0].fix!);
          expect(mirrorWarnings(d).filter((w) => w.code === 'KF406')).toEqual([]);
          // Then one click on the angle fix leaves no warning at all (issue #23: it used to loop).
          const angles = mirrorWarnings(d);
          if (angles.length > 0) expect(mirrorWarnings(applyFix(d, angles[0].fix!))).toEqual([]);
        },
      ),
      SEED,
    );
  });
});

describe('circle mirrors (inversion with flip)', () => {
  const wedge = (flip: boolean | undefined): GraphDoc => ({
    ...triangleDoc(EQUILATERAL, []),
    nodes: [
      { id: 'w1', type: 'reflection', position: [0, 0], params: { line: { a: [0, 0], b: [1, 0] } } },
      {
        id: 'w2',
        type: 'reflection',
        position: [0, 0],
        params: { line: { a: [Math.cos(Math.PI / 3), Math.sin(Math.PI / 3)], b: [0, 0] } },
      },
      {
        id: 'disk',
        type: 'inversion',
        position: [0, 0],
        params: { circle: { c: [0, 0], r: 1 }, ...(flip === undefined ? {} : { flip }) },
      },
      { id: 'out', type: 'render', position: [0, 0], params: {} },
    ],
    edges: ['w1', 'w2', 'disk'].map((id) => ({
      id: `e${id}`,
      from: { node: id, port: 'element' },
      to: { node: 'out', port: 'elements' },
    })),
  });

  it('an inversion saved without flip keeps the outside; flip keeps the inside (outer inversion)', () => {
    const old = evaluateGraph(wedge(undefined), registry);
    expect(old.scene.elements.map((e) => e.kind).sort()).toEqual(['inversion', 'reflection', 'reflection']);
    const flipped = evaluateGraph(wedge(true), registry);
    expect(flipped.scene.elements.map((e) => e.kind).sort()).toEqual([
      'outer-inversion',
      'reflection',
      'reflection',
    ]);
  });

  it('a wedge of two lines at π/3 and the unit circle kept from inside is a clean spherical kaleidoscope', () => {
    expect(mirrorWarnings(wedge(true))).toEqual([]);
  });
});
