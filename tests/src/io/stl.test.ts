/** Binary STL: 84 + 50·n bytes, the triangles read back as written (float32), normals unit and facing out. */
import { describe, expect, it } from 'vitest';
import type { Mesh } from '../../../nodes/geometry/space/marching-tetrahedra.ts';
import { readStl, writeStl } from '../../../src/io/stl.ts';

/** A tetrahedron with outward-facing triangles. */
const tet: Mesh = {
  positions: Float64Array.from([0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1]),
  triangles: Uint32Array.from([0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3]),
};

describe('writeStl / readStl', () => {
  it('writes the header, the count and 50 bytes per triangle, and reads them back', () => {
    const bytes = writeStl(tet, 'Kleinflow test');
    expect(bytes.length).toBe(84 + 4 * 50);
    const { header, triangles } = readStl(bytes);
    expect(header.trim()).toBe('Kleinflow test');
    expect(triangles).toHaveLength(4);
    triangles.forEach((t, i) => {
      t.vertices.forEach((v, j) => {
        const at = tet.triangles[3 * i + j] * 3;
        expect([...v]).toEqual([tet.positions[at], tet.positions[at + 1], tet.positions[at + 2]]);
      });
      expect(Math.hypot(...t.normal)).toBeCloseTo(1, 6);
      // Outward: from the tetrahedron's centroid towards the face.
      const mid = [0, 1, 2].map((k) => t.vertices.reduce((s, v) => s + v[k], 0) / 3 - 0.25);
      expect(mid[0] * t.normal[0] + mid[1] * t.normal[1] + mid[2] * t.normal[2]).toBeGreaterThan(0);
    });
  });

  it('refuses bytes whose length does not match the triangle count', () => {
    expect(() => readStl(writeStl(tet).subarray(0, 120))).toThrow(/triangles need/);
  });
});
