/**
 * The 3D geometry nodes: point-3d, sphere, sphere-4pt, plane — values, read-outs and the messages
 * for bad input (radius ≤ 0, coplanar or coincident points, zero normal).
 */
import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import type { Plane, Sphere, Vec3 } from '../../../nodes/core/scene-3d.ts';
import { dist3 } from '../../../nodes/geometry/space/vec3.ts';
import { evaluateGraph } from '../../../nodes/graph/evaluate.ts';
import { registry } from '../../../nodes/types/index.ts';
import { point3, SEED } from '../geometry/space/arbitraries.ts';
import { doc, edge, node } from '../support/doc.ts';

/** Evaluates one node of `type` with `params`: its outputs, diagnostics and read-out. */
const alone = (type: string, params: Record<string, unknown> = {}) => {
  const result = evaluateGraph(doc([node('n', type, params)]), registry).nodes.get('n')!;
  return { ...result, messages: result.diagnostics.map((d) => `${d.code} ${d.message}`) };
};

describe('point-3d', () => {
  it('outputs (x, y, z) and shows it', () => {
    const r = alone('point-3d', { x: 1, y: -2, z: 0.5 });
    expect(r.outputs?.point).toEqual([1, -2, 0.5]);
    expect(r.readout).toBe('(1, -2, 0.5)');
  });
});

describe('sphere', () => {
  it('outputs centre and radius', () => {
    expect(alone('sphere', { center: [1, 2, 3], radius: 0.5 }).outputs?.sphere).toEqual({
      center: [1, 2, 3],
      radius: 0.5,
    });
  });

  it.each([0, -1])('refuses radius %d with a message on the node', (radius) => {
    const r = alone('sphere', { radius });
    expect(r.outputs).toBeUndefined();
    expect(r.messages).toEqual([`KF303 the sphere's radius must be positive, got ${radius}`]);
  });

  it('refuses a radius that is not a finite number', () => {
    const r = alone('sphere', { radius: 'big' });
    expect(r.outputs).toBeUndefined();
    expect(r.diagnostics[0]!.code).toBe('KF301');
  });

  it('takes its centre from a wired point-3d', () => {
    const ev = evaluateGraph(
      doc(
        [node('p', 'point-3d', { x: 4, y: 5, z: 6 }), node('s', 'sphere')],
        [edge('e', 'p.point', 's.center')],
      ),
      registry,
    );
    expect(ev.nodes.get('s')!.outputs?.sphere).toEqual({ center: [4, 5, 6], radius: 1 });
  });

  it('refuses to take a 2D point for its centre', () => {
    const ev = evaluateGraph(
      doc([node('p', 'point'), node('s', 'sphere')], [edge('e', 'p.point', 's.center')]),
      registry,
    );
    expect(ev.diagnostics.map((d) => d.message)).toContain('cannot connect a point output to a point3 input');
  });
});

describe('sphere-4pt', () => {
  it('the sphere through four points passes through all four (property)', () => {
    fc.assert(
      fc.property(point3, point3, point3, point3, (a, b, c, d) => {
        const r = alone('sphere-4pt', { a, b, c, d });
        const s = r.outputs?.sphere as Sphere | undefined;
        if (!s) {
          expect(r.messages[0]).toMatch(/^KF303 the four points (are coplanar|coincide)/);
          return;
        }
        for (const p of [a, b, c, d] as Vec3[]) expect(dist3(p, s.center)).toBeCloseTo(s.radius, 6);
      }),
      SEED,
    );
  });

  it('refuses coplanar and coincident points', () => {
    expect(alone('sphere-4pt', { a: [0, 0, 0], b: [1, 0, 0], c: [0, 1, 0], d: [1, 1, 0] }).messages).toEqual([
      'KF303 the four points are coplanar (or some coincide): no single sphere passes through them',
    ]);
    expect(alone('sphere-4pt', { a: [1, 1, 1], b: [1, 1, 1], c: [1, 1, 1], d: [1, 1, 1] }).messages).toEqual([
      'KF303 the four points coincide: no sphere passes through them',
    ]);
  });

  it('by default is the unit sphere', () => {
    const s = alone('sphere-4pt').outputs?.sphere as Sphere;
    expect(s.radius).toBeCloseTo(1, 12);
    for (const v of s.center) expect(v).toBeCloseTo(0, 12);
  });
});

describe('sphere-4pt through P, its inverses and Q', () => {
  const s1: Sphere = { center: [-1.5, 0, 0], radius: 1 };
  const s2: Sphere = { center: [1.5, 0, 0], radius: 1 };

  it('passes through P and Q at right angles to S1 and S2 (property)', () => {
    fc.assert(
      fc.property(point3, point3, (p, q) => {
        const r = alone('sphere-4pt', { mode: 'inverses', s1, s2, p, q });
        const s = r.outputs?.sphere as Sphere | undefined;
        if (!s) {
          expect(r.messages[0]).toMatch(/^KF303 (Sphere\(P, P′, P″, Q\)|the control point P)/);
          return;
        }
        fc.pre(s.radius < 1e3);
        for (const x of [p, q]) expect(dist3(x, s.center) / s.radius).toBeCloseTo(1, 6);
        // Orthogonal: |c − c_i|² = r² + r_i² (docs/math-3d.md §1).
        for (const b of [s1, s2])
          expect(dist3(s.center, b.center) ** 2 / (s.radius ** 2 + 1)).toBeCloseTo(1, 6);
      }),
      SEED,
    );
  });

  it('refuses P on the line of the centres (P, P′, P″ and Q then lie in one plane)', () => {
    const r = alone('sphere-4pt', { mode: 'inverses', s1, s2, p: [0, 0, 0], q: [0, 1, 1] });
    expect(r.messages[0]).toMatch(/^KF303 Sphere\(P, P′, P″, Q\): the four points are coplanar/);
  });

  it('offers P and Q as handles in this mode, a–d otherwise', () => {
    const handles = (mode: string) =>
      evaluateGraph(
        doc([node('n', 'sphere-4pt', { mode }), node('r', 'render-3d', { camera: [50, 50, 50] })]),
        registry,
      ).scene3d!.handles.map((h) => h.handle);
    expect(handles('inverses')).toEqual(['p', 'q']);
    expect(handles('four-points')).toEqual(['a', 'b', 'c', 'd']);
  });
});

describe('plane', () => {
  it('normalises the normal, which points to the kept side', () => {
    const p = alone('plane', { point: [0, 0, 1], normal: [0, 0, 5] }).outputs?.plane as Plane;
    expect(p).toEqual({ point: [0, 0, 1], normal: [0, 0, 1] });
  });

  it('refuses a zero normal', () => {
    const r = alone('plane', { normal: [0, 0, 0] });
    expect(r.outputs).toBeUndefined();
    expect(r.messages).toEqual(["KF303 the plane's normal is zero: it has no direction"]);
  });

  it('refuses an inline plane value with a zero normal on an element node', () => {
    const r = alone('plane-reflection', { plane: { point: [0, 0, 0], normal: [0, 0, 0] } });
    expect(r.outputs).toBeUndefined();
    expect(r.diagnostics[0]).toMatchObject({ code: 'KF301', port: 'plane' });
  });

  it('keeps any non-zero normal direction (property)', () => {
    fc.assert(
      fc.property(
        point3,
        point3.filter((n) => Math.hypot(...n) > 1e-3),
        (q, n) => {
          const p = alone('plane', { point: q, normal: n }).outputs?.plane as Plane;
          expect(Math.hypot(...p.normal)).toBeCloseTo(1, 12);
          const l = Math.hypot(...n);
          p.normal.forEach((v, i) => {
            expect(v).toBeCloseTo(n[i]! / l, 12);
          });
        },
      ),
      SEED,
    );
  });
});
