import { describe, expect, it } from 'vitest';
import type { Diagnostic } from '../../../nodes/core/diagnostics.ts';
import { DEFAULT_TILE, LIMITS } from '../../../nodes/core/scene.ts';
import { allFinite, evaluateGraph } from '../../../nodes/graph/evaluate.ts';
import { registry } from '../../../nodes/types/index.ts';
import { doc, edge, node, shuffled } from '../support/doc.ts';
import { testRegistry } from './fixtures.ts';

const only = (ds: readonly Diagnostic[], code: string) => ds.filter((d) => d.code === code);

/** Three inversions into one render; `badRadius` breaks the middle one's circle. */
function threeInversions(badRadius?: number) {
  return doc(
    [
      node('cA', 'circle', { center: [-2, 0], radius: 0.5 }),
      node('cB', 'circle', { center: [0, 0], radius: badRadius ?? 0.5 }),
      node('cC', 'circle', { center: [2, 0], radius: 0.5 }),
      node('iA', 'inversion'),
      node('iB', 'inversion'),
      node('iC', 'inversion'),
      node('out', 'render'),
    ],
    [
      edge('e1', 'cA.circle', 'iA.circle'),
      edge('e2', 'cB.circle', 'iB.circle'),
      edge('e3', 'cC.circle', 'iC.circle'),
      edge('e4', 'iA.element', 'out.elements'),
      edge('e5', 'iB.element', 'out.elements'),
      edge('e6', 'iC.element', 'out.elements'),
    ],
  );
}

describe('evaluateGraph', () => {
  it('builds the scene of a valid graph', () => {
    const ev = evaluateGraph(threeInversions(), registry);
    expect(ev.diagnostics).toEqual([]);
    expect(ev.scene.renderNodeId).toBe('out');
    expect(ev.scene.elements.map((e) => e.nodeId)).toEqual(['iA', 'iB', 'iC']);
    expect(ev.scene.elements[0]).toEqual({ kind: 'inversion', nodeId: 'iA', c: [-2, 0], r: 0.5 });
    expect(ev.scene.tile).toBe(DEFAULT_TILE);
    expect(ev.scene.maxIterations).toBe(LIMITS.defaultMaxIterations);
    expect(ev.scene.view).toEqual({ center: [0, 0], scale: 4 });
    expect(ev.nodes.get('out')?.readout).toBe('3 elements');
  });

  it('a broken node does not take down the rest', () => {
    const ev = evaluateGraph(threeInversions(-1), registry);
    // the other two still reach the scene
    expect(ev.scene.elements.map((e) => e.nodeId)).toEqual(['iA', 'iC']);
    // the circle's own error
    expect(only(ev.diagnostics, 'KF301')).toEqual([
      expect.objectContaining({ nodeId: 'cB', port: 'radius' }),
    ]);
    // the single-input dependant: an error naming the failed node by the title people see (its
    // place among the nodes titled alike), never by its internal id
    const inv = only(ev.diagnostics, 'KF302').find((d) => d.nodeId === 'iB')!;
    expect(inv).toMatchObject({ severity: 'error', port: 'circle' });
    expect(inv.message).toBe('input "circle" has no value because “Circle” (2nd) failed');
    expect(ev.nodes.get('iB')?.outputs).toBeUndefined();
    // the render: a warning naming its broken source
    const render = only(ev.diagnostics, 'KF302').find((d) => d.nodeId === 'out')!;
    expect(render).toMatchObject({ severity: 'warning', port: 'elements' });
    expect(render.message).toContain('“Circle inversion” (2nd)');
    expect(render.message).not.toContain('iB');
    expect(ev.scene.renderNodeId).toBe('out');
  });

  it('a degenerate node (KF303) is contained the same way', () => {
    const ev = evaluateGraph(threeInversions(0), registry);
    expect(only(ev.diagnostics, 'KF303')).toEqual([
      expect.objectContaining({ nodeId: 'cB', severity: 'error' }),
    ]);
    expect(ev.scene.elements).toHaveLength(2);
  });

  it('KF210: no render node → warning and an empty scene', () => {
    const ev = evaluateGraph(
      doc([node('c', 'circle'), node('i', 'inversion')], [edge('e', 'c.circle', 'i.circle')]),
      registry,
    );
    expect(only(ev.diagnostics, 'KF210')).toEqual([expect.objectContaining({ severity: 'warning' })]);
    expect(ev.scene.elements).toEqual([]);
    expect(ev.scene.renderNodeId).toBeNull();
    expect(ev.scene.tile).toBe(DEFAULT_TILE);
    // an empty document is not worth a warning
    expect(evaluateGraph(doc([]), registry).diagnostics).toEqual([]);
  });

  it('KF211: several render nodes → the first by id is drawn', () => {
    const d = doc(
      [node('i', 'inversion'), node('r2', 'render'), node('r1', 'render', { maxIterations: 7 })],
      [edge('e', 'i.element', 'r2.elements')],
    );
    const ev = evaluateGraph(d, registry);
    const [w] = only(ev.diagnostics, 'KF211');
    expect(w).toMatchObject({ severity: 'warning', nodeId: 'r1' });
    expect(w.message).toContain('"r1"');
    expect(ev.scene.renderNodeId).toBe('r1');
    expect(ev.scene.maxIterations).toBe(7);
    expect(ev.scene.elements).toEqual([]);
  });

  it('KF211 names the first render by id even when none of them works', () => {
    const d = doc([node('r2', 'render', { samples: 0 }), node('r1', 'render', { samples: 0 })]);
    const [w] = only(evaluateGraph(d, registry).diagnostics, 'KF211');
    expect(w.nodeId).toBe('r1');
  });

  it('KF308: an optional input whose source leaves that output empty is just unconnected', () => {
    // the hyperbolic example wires the kaleidoscope's disk into the clip; a Euclidean (4, 4, 2) has no disk
    const d = doc(
      [node('k', 'kaleidoscope', { p: 4, q: 4, r: 2 }), node('out', 'render')],
      [edge('e1', 'k.elements', 'out.elements'), edge('e2', 'k.boundary', 'out.clip')],
    );
    const ev = evaluateGraph(d, registry);
    expect(ev.diagnostics).toEqual([
      expect.objectContaining({ code: 'KF308', severity: 'info', nodeId: 'out', port: 'clip' }),
    ]);
    expect(ev.diagnostics[0].message).toContain('"boundary"');
    expect(ev.scene.elements).toHaveLength(3);
    expect(ev.scene.clip).toBeNull();
    // a required input in the same situation is an error, and does not blame a failure
    const nonOptional = doc(
      [node('k', 'kaleidoscope', { p: 4, q: 4, r: 2 }), node('i', 'inversion')],
      [edge('e1', 'k.boundary', 'i.circle')],
    );
    const bad = evaluateGraph(nonOptional, registry).diagnostics.filter((x) => x.nodeId === 'i');
    expect(bad).toEqual([expect.objectContaining({ code: 'KF308', severity: 'error' })]);
  });

  it('render settings: tile, clip, iterations and samples reach the scene', () => {
    const d = doc(
      [
        node('t', 'tile', { mode: 'parity', even: '#ffffff', odd: '#000000' }),
        node('clip', 'circle', { radius: 1 }),
        node('out', 'render', { maxIterations: 33, samples: 9 }),
      ],
      [edge('e1', 't.tile', 'out.tile'), edge('e2', 'clip.circle', 'out.clip')],
    );
    const ev = evaluateGraph(d, registry);
    expect(ev.scene.tile.coloring).toEqual({ mode: 'parity', even: [1, 1, 1], odd: [0, 0, 0] });
    expect(ev.scene.tile.nodeId).toBe('t');
    expect(ev.scene.clip).toEqual({ c: [0, 0], r: 1 });
    expect(ev.scene.maxIterations).toBe(33);
    expect(ev.scene.samples).toBe(9);
    // no elements is fine but worth a note
    expect(only(ev.diagnostics, 'KF402')).toEqual([
      expect.objectContaining({ severity: 'info', nodeId: 'out' }),
    ]);
  });

  it('element order is the graph (evaluation) order, whatever the edge order', () => {
    // b_inv has no dependency; a_inv waits for z_circ: evaluation order b_inv, z_circ, a_inv
    const nodes = [
      node('z_circ', 'circle', { center: [1, 1], radius: 0.3 }),
      node('a_inv', 'inversion'),
      node('b_inv', 'inversion', { circle: { c: [-1, 1], r: 0.3 } }),
      node('c_inv', 'inversion', { circle: { c: [0, -1], r: 0.3 } }),
      node('out', 'render'),
    ];
    const edges = [
      edge('e0', 'z_circ.circle', 'a_inv.circle'),
      edge('e1', 'a_inv.element', 'out.elements'),
      edge('e2', 'c_inv.element', 'out.elements'),
      edge('e3', 'b_inv.element', 'out.elements'),
    ];
    const ev = evaluateGraph(doc(nodes, edges), registry);
    const order = ev.analysis.order.filter((id) => id.endsWith('_inv'));
    expect(order).toEqual(['b_inv', 'c_inv', 'a_inv']);
    expect(ev.scene.elements.map((e) => e.nodeId)).toEqual(order);
    for (let seed = 1; seed <= 6; seed++) {
      const again = evaluateGraph(doc(shuffled(nodes, seed), shuffled(edges, seed + 3)), registry);
      expect(again.scene.elements).toEqual(ev.scene.elements);
    }
  });

  it('a wired number is range-checked like an inline one (KF301)', () => {
    const d = doc(
      [node('n', 'number', { value: 100 }), node('k', 'kaleidoscope'), node('out', 'render')],
      [edge('e1', 'n.value', 'k.p'), edge('e2', 'k.elements', 'out.elements')],
    );
    const ev = evaluateGraph(d, registry);
    expect(only(ev.diagnostics, 'KF301')).toEqual([expect.objectContaining({ nodeId: 'k', port: 'p' })]);
    expect(ev.scene.elements).toEqual([]);
    expect(only(ev.diagnostics, 'KF302')).toEqual([
      expect.objectContaining({ nodeId: 'out', severity: 'warning' }),
    ]);
  });

  it('KF305: a node that throws is reported, the rest goes on', () => {
    const d = doc(
      [node('boom', 'test-throws'), node('m', 'test-many'), node('out', 'render')],
      [edge('e', 'm.element', 'out.elements')],
    );
    const ev = evaluateGraph(d, testRegistry);
    const [t] = only(ev.diagnostics, 'KF305');
    expect(t).toMatchObject({ nodeId: 'boom', severity: 'error' });
    expect(t.message).toContain('kaboom');
    expect(ev.scene.elements).toHaveLength(3);
  });

  it('KF306: a NaN output is caught and the output withheld', () => {
    const d = doc([node('nan', 'test-nan'), node('c', 'circle')], [edge('e', 'nan.point', 'c.center')]);
    const ev = evaluateGraph(d, testRegistry);
    expect(only(ev.diagnostics, 'KF306')).toEqual([
      expect.objectContaining({ nodeId: 'nan', port: 'point' }),
    ]);
    expect(ev.nodes.get('nan')?.outputs).toBeUndefined();
    expect(only(ev.diagnostics, 'KF302')).toEqual([
      expect.objectContaining({ nodeId: 'c', severity: 'error' }),
    ]);
  });

  it('KF401: the render keeps at most LIMITS.maxElements elements', () => {
    const d = doc(
      [node('m', 'test-many', { count: LIMITS.maxElements + 4 }), node('out', 'render')],
      [edge('e', 'm.element', 'out.elements')],
    );
    const ev = evaluateGraph(d, testRegistry);
    expect(only(ev.diagnostics, 'KF401')).toEqual([
      expect.objectContaining({ nodeId: 'out', severity: 'warning' }),
    ]);
    expect(ev.scene.elements).toHaveLength(LIMITS.maxElements);
  });

  it('passes the animation time to nodes', () => {
    const ev = evaluateGraph(doc([node('m', 'test-many')]), testRegistry, { time: 2.5 });
    expect(ev.nodes.get('m')?.readout).toBe('t = 2.5');
    expect(ev.nodes.get('m')?.ctx?.time).toBe(2.5);
  });

  it('collects overlays and handles, with labels; hidden nodes draw nothing', () => {
    const d = doc([
      { ...node('p', 'point', { x: 1, y: 2 }), label: 'A' },
      node('q', 'point', { x: 3, y: 4, visible: false }),
    ]);
    const ev = evaluateGraph(d, registry);
    expect(ev.scene.overlays).toEqual([
      { nodeId: 'p', color: registry.get('point')!.color, label: 'A', shape: { shape: 'point', at: [1, 2] } },
    ]);
    expect(ev.scene.handles).toEqual([{ nodeId: 'p', handle: 'point', at: [1, 2] }]);
  });
});

describe('readouts', () => {
  const mobius = (c1: unknown, c2: unknown) => {
    const ev = evaluateGraph(doc([node('m', 'mobius', { c1, c2 })]), registry);
    return { readout: ev.nodes.get('m')?.readout ?? '', ev };
  };

  it('the Möbius node names its type, and the rotation angle when elliptic', () => {
    expect(mobius({ c: [0, 0], r: 1 }, { c: [0.3, 0], r: 2 }).readout).toMatch(/^hyperbolic/);
    expect(mobius({ c: [-2, 0], r: 1 }, { c: [2, 0], r: 1 }).readout).toMatch(/^hyperbolic/);
    expect(mobius({ c: [0, 0], r: 1 }, { c: [2, 0], r: 1 }).readout).toMatch(/^parabolic/);
    const ell = mobius({ c: [0, 0], r: 1 }, { c: [Math.SQRT2, 0], r: 1 }); // orthogonal: θ = 90°
    expect(ell.readout).toMatch(/^elliptic/);
    expect(ell.readout).toContain('rotation 180°');
    const r3 = Math.sqrt(3.25 - 3 * Math.cos(Math.PI / 3)); // radii 1 and 1.5 crossing at 60°
    const sixty = mobius({ c: [0, 0], r: 1 }, { c: [r3, 0], r: 1.5 });
    expect(sixty.readout).toContain('60°');
    expect(sixty.readout).toContain('rotation 120°');
    expect(sixty.ev.nodes.get('m')?.diagnostics).toEqual([]);
  });

  it('the Möbius node warns (KF304) when an elliptic angle is not π/n', () => {
    const { readout, ev } = mobius({ c: [0, 0], r: 1 }, { c: [1.3, 0], r: 1 });
    expect(readout).toMatch(/^elliptic/);
    expect(only(ev.diagnostics, 'KF304')).toEqual([
      expect.objectContaining({ nodeId: 'm', severity: 'warning' }),
    ]);
    expect(ev.nodes.get('m')?.outputs).toBeDefined();
  });

  it('the kaleidoscope node names its geometry', () => {
    const read = (params: Record<string, unknown>) =>
      evaluateGraph(doc([node('k', 'kaleidoscope', params)]), registry).nodes.get('k')?.readout;
    expect(read({ p: 7, q: 2, r: 3 })).toBe('hyperbolic (7, 2, 3)');
    expect(read({ p: 4, q: 2, r: 3 })).toBe('spherical (4, 2, 3)');
    expect(read({ p: 6, q: 2, r: 3 })).toBe('euclidean (6, 2, 3)');
    expect(read({ p: 3, q: 0, r: 3 })).toBe('hyperbolic (3, ∞, 3)');
  });
});

describe('allFinite', () => {
  it('looks through arrays and objects', () => {
    expect(allFinite({ a: [1, 2, { b: 3 }] })).toBe(true);
    expect(allFinite({ a: [1, 2, { b: Number.NaN }] })).toBe(false);
    expect(allFinite([Number.POSITIVE_INFINITY])).toBe(false);
    expect(allFinite('text')).toBe(true);
  });
});
