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

  it('colours by surface coordinates with the cosine field at each vertex', () => {
    const scene = { ...TWO_SPHERES, coloring: { mode: 'surface' as const, scale: 0.5 } };
    const positions = Float64Array.from([0.7, 0, 0, 0, -0.7, 0, 0.1, 0.2, 0.67]);
    const colours = meshVertexColours(scene, { positions });
    for (let v = 0; v < 3; v++) {
      const want = [0, 1, 2].map((k) => 0.5 + 0.5 * Math.cos((2 * Math.PI * positions[3 * v + k]!) / 0.5));
      expect(near(colours!.subarray(3 * v, 3 * v + 3), want)).toBe(true);
    }
  });

  it('stops with null when its progress callback says so', () => {
    const positions = new Float64Array(3 * 10_000);
    const seen: number[] = [];
    const result = meshVertexColours(TWO_SPHERES, { positions }, (f) => {
      seen.push(f);
      return f < 0.3;
    });
    expect(result).toBeNull();
    expect(seen.at(-1)).toBeGreaterThanOrEqual(0.3);
  });
});
