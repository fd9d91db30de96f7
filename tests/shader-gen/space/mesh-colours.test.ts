/**
 * The render's colours on the mesh (shader-gen/space/mesh-colours.ts): on two spheres coloured by
 * depth the seed's vertices have the seed's colour and its image's the colour a quarter turn on;
 * by surface coordinates every vertex has the cosine field at its own position; cancelling stops.
 */
import { describe, expect, it } from 'vitest';
import { meshVertexColours } from '../../../shader-gen/space/mesh-colours.ts';
import { colouredMesh, IMAGE_COLOUR, SEED_COLOUR, SEED_SIDE_X, TWO_SPHERES } from './coloured-mesh.ts';

const near = (a: ArrayLike<number>, b: ArrayLike<number>, tol = 1e-6) =>
  [0, 1, 2].every((k) => Math.abs(a[k]! - b[k]!) <= tol);

describe('meshVertexColours', () => {
  it('colours the seed with its own colour and its image a quarter turn on the wheel', async () => {
    const { mesh, colours } = await colouredMesh(20);
    const n = mesh.positions.length / 3;
    let seed = 0;
    let image = 0;
    for (let v = 0; v < n; v++) {
      const c = colours.subarray(3 * v, 3 * v + 3);
      if (mesh.positions[3 * v]! < SEED_SIDE_X) {
        expect(near(c, SEED_COLOUR)).toBe(true);
        seed++;
      } else {
        expect(near(c, IMAGE_COLOUR)).toBe(true);
        image++;
      }
    }
    expect(seed).toBeGreaterThan(100);
    expect(image).toBeGreaterThan(20);
    expect(near(SEED_COLOUR, IMAGE_COLOUR, 0.1)).toBe(false);
  });

  it('colours by surface coordinates with the cosine field where the vertex is, to half a cell', async () => {
    const { mesh, cell } = await colouredMesh(20);
    const scene = { ...TWO_SPHERES, coloring: { mode: 'surface' as const, scale: 1 } };
    const colours = (await meshVertexColours(scene, mesh, cell))!;
    // |d field/dx| ≤ π per unit at scale 1: half a cell off moves a channel by at most π·cell/2.
    const tol = (Math.PI * cell) / 2;
    let worst = 0;
    for (let v = 0; v < mesh.positions.length / 3; v++)
      for (let k = 0; k < 3; k++) {
        const want = 0.5 + 0.5 * Math.cos(2 * Math.PI * mesh.positions[3 * v + k]!);
        worst = Math.max(worst, Math.abs(colours[3 * v + k]! - want));
      }
    expect(worst).toBeLessThan(tol);
    expect(worst).toBeGreaterThan(0);
  });

  it('gives both ends of every edge one colour: no vertex takes the colour of a piece beside it', async () => {
    const { mesh, colours, cell } = await colouredMesh(20);
    // Across every mesh edge the colour changes by little: on the two spheres only between seed
    // and image, which no edge joins.
    const t = mesh.triangles;
    let jumps = 0;
    for (let i = 0; i < t.length; i++) {
      const a = 3 * t[i]!;
      const b = 3 * t[i - (i % 3) + ((i + 1) % 3)]!;
      if (!near(colours.subarray(a, a + 3), colours.subarray(b, b + 3), 1e-6)) jumps++;
    }
    expect(jumps).toBe(0);
    expect(cell).toBeGreaterThan(0);
  });

  it('pauses between chunks and stops with null when its progress callback says so', async () => {
    const mesh = { positions: new Float64Array(3 * 10_000), triangles: new Uint32Array(0) };
    const seen: number[] = [];
    let pauses = 0;
    const result = await meshVertexColours(TWO_SPHERES, mesh, 0.1, {
      onProgress: (f) => {
        seen.push(f);
        return f < 0.3;
      },
      pause: async () => {
        pauses++;
      },
    });
    expect(result).toBeNull();
    expect(pauses).toBe(seen.length - 1);
    expect(seen.at(-1)).toBeGreaterThanOrEqual(0.3);
  });
});
