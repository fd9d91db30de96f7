/**
 * The sphairahedron node: six face inversions and one seed into render-3d (finite: spheres and a
 * seed ball; infinite: three plane mirrors, three spheres and a seed box), the inversion sphere's
 * handles, and a clear error on the node for a centre that would turn a face inside out.
 */
import { describe, expect, it } from 'vitest';
import {
  defaultInversionSphere,
  infiniteSphairahedron,
  SPHAIRAHEDRON_TYPES,
} from '../../../nodes/geometry/space/sphairahedron.ts';
import { evaluateGraph } from '../../../nodes/graph/evaluate.ts';
import { registry } from '../../../nodes/types/index.ts';
import { doc, edge, node } from '../support/doc.ts';

const graph = (params: Record<string, unknown>) =>
  doc(
    [node('s', 'sphairahedron', params), node('r', 'render-3d', { camera: [0, -12, 4] })],
    [edge('e1', 's.elements', 'r.elements'), edge('e2', 's.seed', 'r.seeds')],
  );

describe('sphairahedron node', () => {
  it('finite form: six sphere inversions, a seed ball, the inversion sphere draggable', () => {
    const ev = evaluateGraph(graph({ zb: 0.2, zc: -0.1 }), registry);
    expect(ev.diagnostics.filter((d) => d.severity === 'error')).toEqual([]);
    const s = ev.scene3d!;
    expect(s.elements.map((e) => e.kind)).toEqual(Array(6).fill('sphere-inversion'));
    expect(s.seeds.map((x) => x.kind)).toEqual(['sphere']);
    expect(s.handles.filter((h) => h.nodeId === 's').map((h) => h.handle)).toEqual(['center', 'radius']);
  });

  it('infinite form: three plane mirrors and three spheres, a seed box, no handles', () => {
    const ev = evaluateGraph(graph({ shape: 'cube-236-a', form: 'infinite', zb: 0.1, zc: 0.3 }), registry);
    expect(ev.diagnostics.filter((d) => d.severity === 'error')).toEqual([]);
    const s = ev.scene3d!;
    expect(s.elements.map((e) => e.kind)).toEqual([
      ...Array(3).fill('plane-reflection'),
      ...Array(3).fill('sphere-inversion'),
    ]);
    expect(s.seeds.map((x) => x.kind)).toEqual(['box']);
    expect(s.handles.filter((h) => h.nodeId === 's')).toEqual([]);
  });

  it('pentahedral prism: five faces (three planes, two spheres), finite and infinite', () => {
    const finite = evaluateGraph(graph({ shape: 'prism-a', zb: -0.8, center: [0, 0, 2.5] }), registry);
    expect(finite.diagnostics.filter((d) => d.severity === 'error')).toEqual([]);
    expect(finite.scene3d!.elements.map((e) => e.kind)).toEqual(Array(5).fill('sphere-inversion'));
    const infinite = evaluateGraph(graph({ shape: 'prism-f', form: 'infinite', zb: 0.8 }), registry);
    expect(infinite.scene3d!.elements.map((e) => e.kind)).toEqual([
      ...Array(3).fill('plane-reflection'),
      ...Array(2).fill('sphere-inversion'),
    ]);
  });

  it('an inversion centre inside a sphere face is an error on the node, naming the face', () => {
    const ev = evaluateGraph(graph({ center: [0.5, 0, 0] }), registry);
    const errors = ev.diagnostics.filter((d) => d.severity === 'error' && d.nodeId === 's');
    expect(errors).toHaveLength(1);
    expect(errors[0].message).toMatch(/inside sphere S1.*inside out/);
  });

  it('shape parameters where no shape exists (a radius ≤ 0) are an error on the node', () => {
    const ev = evaluateGraph(graph({ zb: 4, zc: -4 }), registry);
    expect(ev.diagnostics.some((d) => d.severity === 'error' && d.nodeId === 's')).toBe(true);
  });

  it.each([
    [1, 0, /bridges/],
    [-1, 0, /tunnels/],
  ])(
    '(zb, zc) = (%s, %s) outside the parameter space is a warning saying what happens (%s), and is drawn',
    (zb, zc, what) => {
      const inf = infiniteSphairahedron(SPHAIRAHEDRON_TYPES[0], zb, zc);
      if (!inf.ok) throw new Error(inf.error);
      const inv = defaultInversionSphere(inf.value);
      for (const form of ['finite', 'infinite']) {
        const ev = evaluateGraph(graph({ zb, zc, form, center: inv.center, radius: inv.radius }), registry);
        const mine = ev.diagnostics.filter((d) => d.nodeId === 's');
        expect(mine.map((d) => [d.code, d.severity])).toEqual([['KF335', 'warning']]);
        expect(mine[0].message).toMatch(what);
        expect(ev.scene3d!.elements).toHaveLength(6);
        expect(ev.scene3d!.seeds).toHaveLength(1);
      }
    },
  );

  it.each(SPHAIRAHEDRON_TYPES.map((t) => [t.id, t] as const))(
    '%s: its example parameters evaluate without warnings, finite and infinite',
    (_, t) => {
      const inf = infiniteSphairahedron(t, ...t.example);
      if (!inf.ok) throw new Error(inf.error);
      const inv = defaultInversionSphere(inf.value);
      const [zb, zc] = t.example;
      for (const form of ['finite', 'infinite']) {
        const ev = evaluateGraph(
          graph({ shape: t.id, form, zb, zc, center: inv.center, radius: inv.radius }),
          registry,
        );
        expect(ev.diagnostics).toEqual([]);
        const faces = inf.value.planes.length + inf.value.spheres.length;
        expect(ev.scene3d!.elements).toHaveLength(faces);
      }
    },
  );
});
