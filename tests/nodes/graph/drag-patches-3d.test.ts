/**
 * 3D handle drags: a drag of every 3D node's handles, re-evaluated, puts the handle where it was
 * dropped (property, every node type with handles3d); wired points, spheres and planes move the
 * upstream node that makes them; random finite parameters never give NaN or an internal error.
 */
import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import type { Vec3 } from '../../../nodes/core/scene-3d.ts';
import { dist3, normalize3, sub3 } from '../../../nodes/geometry/space/vec3.ts';
import type { GraphDoc } from '../../../nodes/graph/document.ts';
import { type NodePatch, originalParams } from '../../../nodes/graph/drag-patches.ts';
import { dragPatches3d } from '../../../nodes/graph/drag-patches-3d.ts';
import { allFinite, evaluateGraph } from '../../../nodes/graph/evaluate.ts';
import { registry } from '../../../nodes/types/index.ts';
import { point3, real, SEED } from '../geometry/space/arbitraries.ts';
import { doc, edge, node } from '../support/doc.ts';

const apply = (d: GraphDoc, patches: readonly NodePatch[]): GraphDoc => ({
  ...d,
  nodes: d.nodes.map((n) => {
    const p = patches.find((x) => x.nodeId === n.id);
    return p ? { ...n, params: { ...n.params, ...p.params } } : n;
  }),
});
const handleAt = (d: GraphDoc, nodeId: string, handle: string): Vec3 | undefined =>
  evaluateGraph(d, registry).scene3d?.handles.find((h) => h.nodeId === nodeId && h.handle === handle)?.at;
/** A render-3d beside the node, so the evaluation has a scene3d to hold the handles. */
const withRender = (
  n: ReturnType<typeof node>,
  edges: ReturnType<typeof edge>[] = [],
  more: ReturnType<typeof node>[] = [],
) => doc([...more, n, node('r', 'render-3d', { camera: [50, -60, 40] })], edges);

const TYPES_WITH_HANDLES = registry.all.filter((d) => d.handles3d).map((d) => d.type);

describe('dragPatches3d', () => {
  it('covers every 3D node type with handles', () => {
    expect(TYPES_WITH_HANDLES).toEqual(
      expect.arrayContaining([
        'point-3d',
        'sphere',
        'sphere-4pt',
        'plane',
        'sphere-inversion',
        'mobius-3d',
        'seed-sphere',
        'seed-box',
      ]),
    );
  });

  it.each(TYPES_WITH_HANDLES)(
    '%s: a dragged handle, re-evaluated, is where it was dropped (property)',
    (type) => {
      const before = withRender(node('n', type));
      const handles = evaluateGraph(before, registry).scene3d!.handles.filter((h) => h.nodeId === 'n');
      expect(handles.length).toBeGreaterThan(0);
      fc.assert(
        fc.property(fc.constantFrom(...handles.map((h) => h.handle)), point3, (handle, to) => {
          const centre = handles.find(
            (h) =>
              h.handle ===
              handle.replace(/(radius|corner|normal)$/, (m) => (m === 'normal' ? 'point' : 'center')),
          );
          fc.pre(!centre || dist3(centre.at, to) > 1e-3);
          const after = apply(
            before,
            dragPatches3d(evaluateGraph(before, registry), { nodeId: 'n', handle }, to),
          );
          const at = handleAt(after, 'n', handle)!;
          const newCentre = centre && handleAt(after, 'n', centre.handle)!;
          if (handle.endsWith('radius')) {
            // A point on the sphere: the new radius is the distance dropped at.
            expect(dist3(at, newCentre!)).toBeCloseTo(dist3(to, centre!.at), 9);
          } else if (handle.endsWith('corner')) {
            sub3(at, newCentre!).forEach((v, i) => {
              expect(v).toBeCloseTo(Math.abs(to[i]! - centre!.at[i]!), 9);
            });
          } else if (handle.endsWith('.normal')) {
            // An inline plane's normal is stored unit: the handle points where it was dropped.
            const want = normalize3(sub3(to, centre!.at));
            sub3(at, newCentre!).forEach((v, i) => {
              expect(v).toBeCloseTo(want[i]!, 9);
            });
          } else {
            at.forEach((v, i) => {
              expect(v).toBeCloseTo(to[i]!, 9);
            });
          }
        }),
        { ...SEED, numRuns: 60 },
      );
    },
  );

  it('forwards a wired centre to the point-3d that makes it', () => {
    const d = withRender(
      node('s', 'sphere', { radius: 2 }),
      [edge('e', 'p.point', 's.center')],
      [node('p', 'point-3d')],
    );
    expect(dragPatches3d(evaluateGraph(d, registry), { nodeId: 's', handle: 'center' }, [1, 2, 3])).toEqual([
      { nodeId: 'p', params: { x: 1, y: 2, z: 3 } },
    ]);
    // The radius handle stays with the sphere itself.
    expect(dragPatches3d(evaluateGraph(d, registry), { nodeId: 's', handle: 'radius' }, [0, 0, 5])).toEqual([
      { nodeId: 's', params: { radius: 5 } },
    ]);
  });

  it('forwards a wired sphere through its centre and radius handles, and on to a wired point', () => {
    const d = withRender(
      node('m', 'sphere-inversion'),
      [edge('e1', 'p.point', 's.center'), edge('e2', 's.sphere', 'm.sphere')],
      [node('p', 'point-3d', { x: 1 }), node('s', 'sphere', { radius: 0.5 })],
    );
    const ev = evaluateGraph(d, registry);
    expect(dragPatches3d(ev, { nodeId: 'm', handle: 'sphere.center' }, [4, 5, 6])).toEqual([
      { nodeId: 'p', params: { x: 4, y: 5, z: 6 } },
    ]);
    expect(dragPatches3d(ev, { nodeId: 'm', handle: 'sphere.radius' }, [1, 0, 2])).toEqual([
      { nodeId: 's', params: { radius: 2 } },
    ]);
  });

  it('restores the values before a drag (Escape), defaults included', () => {
    const d = withRender(node('m', 'sphere-inversion'), [], [node('p', 'point-3d', { x: 2 })]);
    const ev = evaluateGraph(d, registry);
    const moved = [
      ...dragPatches3d(ev, { nodeId: 'm', handle: 'sphere.center' }, [1, 1, 1]),
      ...dragPatches3d(ev, { nodeId: 'p', handle: 'point' }, [3, 4, 5]),
    ];
    expect(originalParams(ev, moved)).toEqual([
      { nodeId: 'm', params: { sphere: { center: [0, 0, 0], radius: 1 } } },
      { nodeId: 'p', params: { x: 2, y: 0, z: 0 } },
    ]);
  });

  it('forwards a wired plane through its point and normal handles', () => {
    const d = withRender(
      node('m', 'plane-reflection'),
      [edge('e', 'q.plane', 'm.plane')],
      [node('q', 'plane')],
    );
    const ev = evaluateGraph(d, registry);
    expect(dragPatches3d(ev, { nodeId: 'm', handle: 'plane.point' }, [0, 0, 2])).toEqual([
      { nodeId: 'q', params: { point: [0, 0, 2] } },
    ]);
    expect(dragPatches3d(ev, { nodeId: 'm', handle: 'plane.normal' }, [0, 3, 0])).toEqual([
      { nodeId: 'q', params: { normal: [0, 3, 0] } },
    ]);
  });
});

/** Finite numbers of every size a user might type, including the awkward ones. */
const num = fc.oneof(real(-10, 10), real(-1e6, 1e6), fc.constantFrom(0, 1e-12, -1e-12, 1e6, -1));
const vec = fc.tuple(num, num, num);
const arbitraryOf: Record<string, fc.Arbitrary<unknown>> = {
  number: num,
  point3: vec,
  sphere: fc.record({ center: vec, radius: num }),
  plane: fc.record({ point: vec, normal: vec }),
};

describe('3D evaluation with random finite parameters', () => {
  const types = registry.all.filter((d) => d.category === '3D' || d.type === 'render-3d');

  it.each(types.map((d) => d.type))('%s never yields NaN or an internal error (property)', (type) => {
    const def = registry.get(type)!;
    const inputs = Object.entries(def.inputs).filter(([, s]) => arbitraryOf[s.type]);
    const params = fc.record(Object.fromEntries(inputs.map(([k, s]) => [k, arbitraryOf[s.type]!])));
    fc.assert(
      fc.property(params, (p) => {
        const ev = evaluateGraph(withRender(node('n', type, p)), registry);
        for (const d of ev.diagnostics) expect(['KF305', 'KF306']).not.toContain(d.code);
        const result = ev.nodes.get('n')!;
        if (result.outputs) expect(allFinite(result.outputs)).toBe(true);
        if (ev.scene3d) expect(allFinite(ev.scene3d, -100)).toBe(true);
      }),
      { ...SEED, numRuns: 100 },
    );
  });

  it('a scene of random elements and seeds is finite everywhere (property)', () => {
    const sphere = fc.record({ center: vec, radius: num });
    fc.assert(
      fc.property(fc.array(sphere, { minLength: 1, maxLength: 4 }), sphere, vec, (spheres, seed, camera) => {
        const mirrors = spheres.map((s, i) => node(`m${i}`, 'sphere-inversion', { sphere: s }));
        const d = doc(
          [...mirrors, node('s', 'seed-sphere', seed), node('r', 'render-3d', { camera })],
          [
            ...mirrors.map((m, i) => edge(`e${i}`, `${m.id}.element`, 'r.elements')),
            edge('es', 's.seed', 'r.seeds'),
          ],
        );
        const ev = evaluateGraph(d, registry);
        for (const x of ev.diagnostics) expect(['KF305', 'KF306']).not.toContain(x.code);
        if (ev.scene3d) expect(allFinite(ev.scene3d, -100)).toBe(true);
      }),
      { ...SEED, numRuns: 150 },
    );
  });
});
