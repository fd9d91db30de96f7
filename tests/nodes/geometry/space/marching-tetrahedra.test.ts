/**
 * Marching tetrahedra (docs/math-3d.md "Voxel mesh (paper §5.3.2)"): for any solid on a grid the
 * mesh is closed and consistently oriented (each directed edge once, its reverse once) with positive
 * volume, and a ball's mesh has about the ball's volume and contains its centre.
 */
import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import {
  gridPoint,
  marchingTetrahedra,
  meshVolume,
  sampleIndex,
  type VoxelGrid,
} from '../../../../nodes/geometry/space/marching-tetrahedra.ts';
import { add3, len3, scale3, sub3, type Vec3 } from '../../../../nodes/geometry/space/vec3.ts';
import { SEED } from './arbitraries.ts';
import { edgeProblems, insideMesh } from './mesh-checks.ts';

const grid = (n: number): VoxelGrid => ({ min: [0, 0, 0], step: [1, 1, 1], nx: n, ny: n, nz: n });

describe('marchingTetrahedra', () => {
  it('any solid gives a closed, consistently oriented mesh of positive volume', () => {
    fc.assert(
      fc.property(
        fc
          .integer({ min: 2, max: 7 })
          .chain((n) =>
            fc.tuple(fc.constant(n), fc.uint8Array({ minLength: (n + 1) ** 3, maxLength: (n + 1) ** 3 })),
          ),
        fc.integer({ min: 1, max: 250 }),
        ([n, noise], density) => {
          const g = grid(n);
          const solid = Uint8Array.from(noise, (v) => (v < density ? 1 : 0));
          const mesh = marchingTetrahedra(g, solid)!;
          expect(edgeProblems(mesh)).toEqual([]);
          let interiorSolid = 0;
          for (let k = 1; k < n; k++)
            for (let j = 1; j < n; j++)
              for (let i = 1; i < n; i++) interiorSolid += solid[sampleIndex(g, i, j, k)];
          if (interiorSolid === 0) expect(mesh.triangles.length).toBe(0);
          else expect(meshVolume(mesh)).toBeGreaterThan(0);
        },
      ),
      SEED,
    );
  });

  it('a ball: volume near 4πr³/3 with vertices on the sphere, the centre inside, far points outside', () => {
    const n = 24;
    const g: VoxelGrid = { min: [-1.2, -1.2, -1.2], step: [0.1, 0.1, 0.1], nx: n, ny: n, nz: n };
    const centre: Vec3 = [0.03, -0.02, 0.01];
    const r = 0.9;
    const inBall = (p: Vec3) => len3(sub3(p, centre)) < r;
    const solid = new Uint8Array((n + 1) ** 3);
    for (let k = 0; k <= n; k++)
      for (let j = 0; j <= n; j++)
        for (let i = 0; i <= n; i++) solid[sampleIndex(g, i, j, k)] = inBall(gridPoint(g, i, j, k)) ? 1 : 0;
    const onSphere = (a: Vec3, b: Vec3): Vec3 => {
      let lo = a;
      let hi = b;
      for (let s = 0; s < 30; s++) {
        const m = scale3(add3(lo, hi), 0.5);
        if (inBall(m)) lo = m;
        else hi = m;
      }
      return lo;
    };
    const mesh = marchingTetrahedra(g, solid, { crossing: onSphere })!;
    expect(edgeProblems(mesh)).toEqual([]);
    expect(meshVolume(mesh) / ((4 / 3) * Math.PI * r ** 3)).toBeGreaterThan(0.97);
    expect(meshVolume(mesh) / ((4 / 3) * Math.PI * r ** 3)).toBeLessThan(1.0001);
    expect(insideMesh(mesh, centre)).toBe(true);
    expect(insideMesh(mesh, [1.1, 0, 0])).toBe(false);
  });

  it('stops with null when the layer callback says so', () => {
    const solid = new Uint8Array(6 ** 3).fill(1);
    let layers = 0;
    expect(marchingTetrahedra(grid(5), solid, { onLayer: () => ++layers < 2 })).toBeNull();
    expect(layers).toBe(2);
  });
});
