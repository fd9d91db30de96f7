/**
 * The parameter space of a sphairahedron type (docs/math-3d.md "The parameter space: bridges and
 * tunnels"): the published examples are inside it; outside it a stray edge on the open side is a
 * bridge, under the spheres a tunnel, a hole in the floor a tunnel; a radius ≤ 0 is degenerate.
 */
import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import { infiniteSphairahedron } from '../../../../nodes/geometry/space/sphairahedron.ts';
import { floorTop } from '../../../../nodes/geometry/space/sphairahedron-shared.ts';
import { spaceClass, withOutside } from '../../../../nodes/geometry/space/sphairahedron-space.ts';
import { CUBE_TYPES, SPHAIRAHEDRON_TYPES } from '../../../../nodes/geometry/space/sphairahedron-types.ts';

const SEED = { seed: 2511, numRuns: 60 };
const cubeA = CUBE_TYPES[0];
const classOf = (zb: number, zc: number, type = cubeA) => spaceClass(infiniteSphairahedron(type, zb, zc));

describe('sphairahedron parameter space', () => {
  it.each(SPHAIRAHEDRON_TYPES.map((t) => [t.id, t] as const))('%s: its example is valid', (_, t) => {
    expect(spaceClass(infiniteSphairahedron(t, ...t.example))).toBe('valid');
  });

  it('cube A: a sphere raised through its far wall makes a bridge, lowered through it a tunnel', () => {
    expect(classOf(0.8, 0.3)).toBe('valid');
    expect(classOf(1, 0)).toBe('bridge');
    expect(classOf(-1, 0)).toBe('tunnel');
    expect(classOf(0.9, 0.9)).toBe('bridge');
    expect(classOf(1.2, -0.9)).toBe('bridge-tunnel');
    expect(classOf(-1.5, 1.5)).toBe('degenerate');
  });

  it('the bridge names the sphere and the plane it crosses', () => {
    const r = infiniteSphairahedron(cubeA, 1, 0);
    if (!r.ok) throw new Error(r.error);
    expect(r.value.outside).toEqual([{ kind: 'bridge', sphere: 'S2', plane: 'F2' }]);
  });

  it('a hole in the floor is a tunnel with the floor under the covered part; no cover at all is degenerate', () => {
    const corners = cubeA.prism.map((_, k) => {
      const a = (2 * Math.PI * k) / 3;
      return [Math.cos(a), Math.sin(a), 0] as const;
    });
    const small = { center: [1, 0, 0] as const, radius: 0.5 };
    const floor = floorTop(corners, [small]);
    expect(floor.ok && floor.value.hole).toBe(true);
    const shape = withOutside({ type: cubeA, corners, planes: [], spheres: [small] }, []);
    expect(spaceClass(shape)).toBe('tunnel');
    expect(floorTop(corners, [{ center: [5, 5, 0], radius: 0.1 }]).ok).toBe(false);
  });

  it('anywhere in the plane: degenerate exactly when refused; otherwise positive radii and a finite floor', () => {
    fc.assert(
      fc.property(
        fc.constantFrom(...SPHAIRAHEDRON_TYPES),
        fc.double({ min: -2.5, max: 2.5, noNaN: true }),
        fc.double({ min: -2.5, max: 2.5, noNaN: true }),
        (type, zb, zc) => {
          const r = infiniteSphairahedron(type, zb, zc);
          expect(spaceClass(r) === 'degenerate').toBe(!r.ok);
          if (r.ok) {
            expect(r.value.spheres.every((s) => s.radius > 0)).toBe(true);
            expect(Number.isFinite(r.value.floorTop)).toBe(true);
          }
        },
      ),
      SEED,
    );
  });
});
