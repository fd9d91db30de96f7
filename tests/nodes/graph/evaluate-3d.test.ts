/**
 * The 3D scene: a render-3d node makes the Evaluation's scene3d (elements in graph order, seeds,
 * camera, clamped settings, overlays and handles), leaves the 2D scene empty, and 3D and 2D
 * sockets never connect.
 */
import { describe, expect, it } from 'vitest';
import { evaluateGraph } from '../../../nodes/graph/evaluate.ts';
import { registry } from '../../../nodes/types/index.ts';
import { doc, edge, node } from '../support/doc.ts';

const sixMirrors = () =>
  [
    [2, 0, 0],
    [-2, 0, 0],
    [0, 2, 0],
    [0, -2, 0],
    [0, 0, 2],
    [0, 0, -2],
  ].map((c, i) => node(`m${i}`, 'sphere-inversion', { sphere: { center: c, radius: 1 } }));

describe('evaluate: render-3d', () => {
  it('builds scene3d from the elements and seeds wired in, and leaves the 2D scene empty', () => {
    const mirrors = sixMirrors();
    const d = doc(
      [...mirrors, node('s', 'seed-sphere', { radius: 0.5 }), node('r', 'render-3d')],
      [
        ...mirrors.map((m, i) => edge(`e${i}`, `${m.id}.element`, 'r.elements')),
        edge('es', 's.seed', 'r.seeds'),
      ],
    );
    const ev = evaluateGraph(d, registry);
    expect(ev.diagnostics.filter((x) => x.severity !== 'info')).toEqual([]);
    const s = ev.scene3d!;
    expect(s.kind).toBe('3d');
    expect(s.renderNodeId).toBe('r');
    expect(s.elements.map((e) => e.kind)).toEqual(Array(6).fill('sphere-inversion'));
    expect(s.seeds).toHaveLength(1);
    expect(s.seeds[0]).toMatchObject({
      kind: 'sphere',
      nodeId: 's',
      sphere: { center: [0, 0, 0], radius: 0.5 },
    });
    expect(ev.scene.elements).toEqual([]);
    expect(ev.scene.renderNodeId).toBeNull();
    // Every mirror and the seed is drawn and has handles.
    expect(new Set(s.overlays.map((o) => o.nodeId))).toEqual(new Set([...mirrors.map((m) => m.id), 's']));
    expect(s.handles.filter((h) => h.nodeId === 's').map((h) => h.handle)).toEqual(['center', 'radius']);
  });

  it('keeps 2D documents as they were (no scene3d)', () => {
    const ev = evaluateGraph(
      doc(
        [node('c', 'circle'), node('i', 'inversion'), node('r', 'render')],
        [edge('e', 'i.element', 'r.elements')],
      ),
      registry,
    );
    expect(ev.scene3d).toBeNull();
    expect(ev.scene.renderNodeId).toBe('r');
  });

  it('refuses a 3D element wired into the 2D render, and a 2D element into render-3d', () => {
    const ev = evaluateGraph(
      doc(
        [
          node('m', 'sphere-inversion'),
          node('i', 'inversion'),
          node('r2', 'render'),
          node('r3', 'render-3d'),
        ],
        [edge('a', 'm.element', 'r2.elements'), edge('b', 'i.element', 'r3.elements')],
      ),
      registry,
    );
    const mismatches = ev.diagnostics.filter((x) => x.code === 'KF206').map((x) => x.message);
    expect(mismatches).toEqual([
      'cannot connect a element3 output to a element input',
      'cannot connect a element output to a element3 input',
    ]);
  });

  it('clamps out-of-range settings with a message and never puts NaN in the scene', () => {
    const ev = evaluateGraph(
      doc([
        node('r', 'render-3d', { maxIterations: 0, marchSteps: 1e9, deScale: 3, samples: 2.5, fov: 500 }),
      ]),
      registry,
    );
    const s = ev.scene3d!;
    expect(s.maxIterations).toBe(1);
    expect(s.marchSteps).toBe(2000);
    expect(s.deScale).toBe(1);
    expect(s.samples).toBe(3);
    expect(s.camera.fovDeg).toBe(170);
    const clamped = ev.nodes
      .get('r')!
      .diagnostics.filter((x) => x.code === 'KF402' && x.severity === 'warning');
    expect(clamped.map((x) => x.port)).toEqual(['fov', 'maxIterations', 'marchSteps', 'deScale', 'samples']);
    expect(clamped[3]!.message).toBe('deScale 3 is outside 0.01…1: 1 is used');
  });

  it('warns when the camera is inside a mirror or a seed, and names the element whose region holds a seed', () => {
    const ev = evaluateGraph(
      doc(
        [
          node('m', 'sphere-inversion', { sphere: { center: [0, 0, 0], radius: 3 } }),
          node('s', 'seed-sphere', { center: [2.9, 0, 0], radius: 0.5 }),
          node('r', 'render-3d', { camera: [1, 1, 1] }),
        ],
        [edge('a', 'm.element', 'r.elements'), edge('b', 's.seed', 'r.seeds')],
      ),
      registry,
    );
    const msgs = ev.nodes.get('r')!.diagnostics.map((x) => `${x.code} ${x.message}`);
    expect(msgs.some((m) => m.startsWith('KF313 the camera is inside the region of element "m"'))).toBe(true);
    expect(msgs).toContain(
      'KF314 seed "s" is not in the fundamental domain: the region of element "m" holds part of it, so its images overlap (move the seed out of that region)',
    );
    expect(ev.scene3d).not.toBeNull();
  });

  it('fails the render when the camera looks at itself (no scene3d rather than NaN)', () => {
    const ev = evaluateGraph(
      doc([node('r', 'render-3d', { camera: [1, 2, 3], target: [1, 2, 3] })]),
      registry,
    );
    expect(ev.scene3d).toBeNull();
    expect(ev.nodes.get('r')!.diagnostics[0]!.code).toBe('KF303');
  });

  it.each([
    ['point-3d', 'x', 'NaN-ish', /x: expected a number/],
    ['sphere', 'center', [1, 2], /center: expected a point3 value, got \[1,2\]/],
    ['sphere-inversion', 'sphere', { center: [0, 0], radius: 1 }, /sphere: expected a sphere value/],
    ['plane-reflection', 'plane', { point: [0, 0, 0] }, /plane: expected a plane value/],
  ])('refuses a malformed inline %s value with the port named (KF301)', (type, key, value, message) => {
    const r = evaluateGraph(doc([node('n', type, { [key]: value })]), registry).nodes.get('n')!;
    expect(r.outputs).toBeUndefined();
    expect(r.diagnostics[0]).toMatchObject({ code: 'KF301', port: key, path: `nodes[0].params.${key}` });
    expect(r.diagnostics[0]!.message).toMatch(message);
  });

  it('counts render-3d as the render node: no KF210 alone; with a 2D render, the first by id is drawn', () => {
    const alone = evaluateGraph(
      doc([node('s', 'seed-sphere'), node('r', 'render-3d')], [edge('e', 's.seed', 'r.seeds')]),
      registry,
    );
    expect(alone.diagnostics.map((d) => d.code)).not.toContain('KF210');
    const both = (id3: string) =>
      evaluateGraph(doc([node('b2', 'render'), node(id3, 'render-3d')]), registry);
    const first3d = both('a3');
    expect(first3d.scene3d?.renderNodeId).toBe('a3');
    expect(first3d.scene.renderNodeId).toBeNull();
    expect(first3d.diagnostics.find((d) => d.code === 'KF211')?.message).toBe(
      'several render nodes; "a3" (first by id) is drawn',
    );
    const first2d = both('c3');
    expect(first2d.scene3d).toBeNull();
    expect(first2d.scene.renderNodeId).toBe('b2');
  });
});
