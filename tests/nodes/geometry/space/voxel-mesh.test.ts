/**
 * The mesh of a 3D scene's solid (docs/math-3d.md "Voxel mesh (paper §5.3.2)"): closed, oriented,
 * positive volume, and it agrees with the CPU inside test at random points away from its surface;
 * progress rises to 1 and Cancel stops it; scenes without a known bound ask for one.
 */
import { describe, expect, it } from 'vitest';
import type { NodeElement3d, Scene3d, Seed3d } from '../../../../nodes/core/scene-3d.ts';
import { meshVolume } from '../../../../nodes/geometry/space/marching-tetrahedra.ts';
import {
  CAKE_TYPES,
  CUBE_TYPES,
  finiteElements,
  finiteSphairahedron,
  infiniteSphairahedron,
} from '../../../../nodes/geometry/space/sphairahedron.ts';
import { add3, type Vec3 } from '../../../../nodes/geometry/space/vec3.ts';
import { meshScene3d, type SceneMesh, solidAt } from '../../../../nodes/geometry/space/voxel-mesh.ts';
import { edgeProblems, insideMesh } from './mesh-checks.ts';

type MeshScene = Pick<Scene3d, 'elements' | 'seeds' | 'maxIterations'>;

/** Fig. 11: six inversion spheres at ±2 on the axes and a seed ball in the middle. */
const fig11: MeshScene = {
  elements: (
    [
      [2, 0, 0],
      [-2, 0, 0],
      [0, 2, 0],
      [0, -2, 0],
      [0, 0, 2],
      [0, 0, -2],
    ] as Vec3[]
  ).map(
    (center, i): NodeElement3d => ({
      kind: 'sphere-inversion',
      nodeId: `m${i}`,
      sphere: { center, radius: 1 },
    }),
  ),
  seeds: [
    { kind: 'sphere', nodeId: 's', sphere: { center: [0, 0, 0], radius: 0.8 }, color: [1, 1, 1] } as Seed3d,
  ],
  maxIterations: 20,
};

/** Deterministic points (mulberry32). */
function randomPoints(n: number, lo: Vec3, hi: Vec3, seed: number): Vec3[] {
  let a = seed >>> 0;
  const rand = () => {
    a = (a + 0x6d2b79f5) >>> 0;
    let t = a;
    t = Math.imul(t ^ (t >>> 15), t | 1);
    t ^= t + Math.imul(t ^ (t >>> 7), t | 61);
    return ((t ^ (t >>> 14)) >>> 0) / 4294967296;
  };
  return Array.from(
    { length: n },
    () => [0, 1, 2].map((k) => lo[k] + (hi[k] - lo[k]) * rand()) as unknown as Vec3,
  );
}

/** Points whose 27 neighbours two cells around agree with them: away from the surface. */
function checkAgreement(scene: MeshScene, result: SceneMesh, n: number) {
  const { mesh, bounds, grid } = result;
  const h = 2 * grid.step[0];
  let checked = 0;
  let solidChecked = 0;
  for (const p of randomPoints(n, bounds.min, bounds.max, 7)) {
    const inside = solidAt(scene, p);
    let uniform = true;
    for (const dx of [-h, 0, h])
      for (const dy of [-h, 0, h])
        for (const dz of [-h, 0, h]) if (solidAt(scene, add3(p, [dx, dy, dz])) !== inside) uniform = false;
    if (!uniform) continue;
    checked++;
    if (inside) solidChecked++;
    expect(insideMesh(mesh, p), `at ${p.join(', ')}`).toBe(inside);
  }
  expect(checked).toBeGreaterThan(n / 4);
  expect(solidChecked).toBeGreaterThan(0);
}

describe('meshScene3d', () => {
  it('Fig. 11: closed, oriented, positive volume, agrees with the inside test away from the surface', async () => {
    const progress: number[] = [];
    const r = await meshScene3d(fig11, { resolution: 28, onProgress: (f) => progress.push(f) > 0 });
    if (!r?.ok) throw new Error(r ? r.error : 'cancelled');
    expect(edgeProblems(r.value.mesh)).toEqual([]);
    expect(meshVolume(r.value.mesh)).toBeGreaterThan(0.9 * (4 / 3) * Math.PI * 0.8 ** 3);
    expect(progress.every((f, i) => i === 0 || f >= progress[i - 1])).toBe(true);
    expect(progress.at(-1)).toBe(1);
    checkAgreement(fig11, r.value, 150);
  });

  it.each([
    ['cube A', CUBE_TYPES[0]!, 0.25, -0.15],
    ['cake B', CAKE_TYPES[1]!, 0.3, 0],
  ] as const)(
    'the finite sphairahedron (%s quasi-sphere): closed, oriented, positive volume, agrees with the inside test',
    async (_, type, zb, zc) => {
      const inf = infiniteSphairahedron(type, zb, zc);
      if (!inf.ok) throw new Error(inf.error);
      const fin = finiteSphairahedron(inf.value, { center: [0, 0, 1.6], radius: 1.5 });
      if (!fin.ok) throw new Error(fin.error);
      const scene: MeshScene = {
        elements: finiteElements(fin.value).map((e) => ({ ...e, nodeId: 'sph' })),
        seeds: [{ kind: 'sphere', nodeId: 'sph', sphere: fin.value.seed, color: [1, 1, 1], clipped: true }],
        maxIterations: 30,
      };
      const r = await meshScene3d(scene, { resolution: 24, refine: 4 });
      if (!r?.ok) throw new Error(r ? r.error : 'cancelled');
      expect(edgeProblems(r.value.mesh)).toEqual([]);
      expect(meshVolume(r.value.mesh)).toBeGreaterThan(0);
      checkAgreement(scene, r.value, 100);
    },
  );

  it('cancels when the progress callback returns false', async () => {
    let calls = 0;
    expect(await meshScene3d(fig11, { resolution: 16, onProgress: () => ++calls < 3 })).toBeNull();
    expect(calls).toBe(3);
  });

  it('asks for bounds when plane mirrors make the orbit unbounded, and refuses a bad resolution', async () => {
    const mirror: NodeElement3d = {
      kind: 'plane-reflection',
      nodeId: 'p',
      plane: { point: [0, 0, 3], normal: [0, 0, -1] },
    };
    const plane: MeshScene = { ...fig11, elements: [mirror] };
    const r = await meshScene3d(plane, { resolution: 16 });
    expect(r?.ok === false && r.error).toMatch(/unbounded.*give bounds/);
    const b = await meshScene3d(plane, { resolution: 12, bounds: { min: [-1, -1, -1], max: [1, 1, 1] } });
    if (!b?.ok) throw new Error(b ? b.error : 'cancelled');
    expect(edgeProblems(b.value.mesh)).toEqual([]);
    expect((await meshScene3d(fig11, { resolution: 2.5 }))?.ok).toBe(false);
  });
});
