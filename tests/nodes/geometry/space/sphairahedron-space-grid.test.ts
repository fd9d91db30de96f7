/**
 * The parameter-space panel's grid (paper Fig. 30): each cell is the class of its centre, rows run
 * from the top (zc largest), and types with zb only take one row, the zb axis.
 */
import { describe, expect, it } from 'vitest';
import { infiniteSphairahedron } from '../../../../nodes/geometry/space/sphairahedron.ts';
import { SPACE_CLASSES, spaceClass } from '../../../../nodes/geometry/space/sphairahedron-space.ts';
import { spaceGrid } from '../../../../nodes/geometry/space/sphairahedron-space-grid.ts';
import { sphairahedronTypeById } from '../../../../nodes/geometry/space/sphairahedron-types.ts';

describe('spaceGrid', () => {
  it('cube A on [−2.5, 2.5]²: every cell is the class at its centre, the valid cell holds the origin', () => {
    const type = sphairahedronTypeById('cube-a')!;
    const n = 10;
    const grid = spaceGrid(type, { center: [0, 0], half: 2.5 }, n);
    expect(grid).toHaveLength(n * n);
    for (let j = 0; j < n; j++)
      for (let i = 0; i < n; i++) {
        const zb = -2.5 + (i + 0.5) * 0.5;
        const zc = 2.5 - (j + 0.5) * 0.5;
        expect(SPACE_CLASSES[grid[j * n + i]!]).toBe(spaceClass(infiniteSphairahedron(type, zb, zc)));
      }
    // (0.25, 0.25) and (1.25, -1.25): valid, and no shape.
    expect(SPACE_CLASSES[grid[4 * n + 5]!]).toBe('valid');
    expect(SPACE_CLASSES[grid[7 * n + 7]!]).toBe(spaceClass(infiniteSphairahedron(type, 1.25, -1.25)));
    expect(new Set(grid).size).toBeGreaterThanOrEqual(4);
  });

  it('a cake (zb only) gives one row along the zb axis', () => {
    const type = sphairahedronTypeById('cake-a')!;
    const grid = spaceGrid(type, { center: [0, 0], half: 2.5 }, 20, 1);
    expect(grid).toHaveLength(20);
    expect(SPACE_CLASSES[grid[10]!]).toBe('valid');
    expect(SPACE_CLASSES[grid[0]!]).not.toBe('valid');
  });
});
