/** The mesh formats by extension (src/io/mesh-file.ts): any case, the last extension only, STL without colours. */
import { describe, expect, it } from 'vitest';
import type { Mesh } from '../../../nodes/geometry/space/marching-tetrahedra.ts';
import { MESH_EXTENSIONS, meshFileBytes, meshFormatOf } from '../../../src/io/mesh-file.ts';
import { readStl } from '../../../src/io/stl.ts';

const tet: Mesh = {
  positions: Float64Array.from([0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1]),
  triangles: Uint32Array.from([0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3]),
};

describe('mesh file formats', () => {
  it('takes the format from the last extension, in any case', () => {
    expect(meshFormatOf('a/model.stl')).toBe('stl');
    expect(meshFormatOf('model.GLB')).toBe('glb');
    expect(meshFormatOf('print.3mf')).toBe('3mf');
    expect(meshFormatOf('model.3mf.obj')).toBeNull();
    expect(meshFormatOf('stl')).toBeNull();
    expect(meshFormatOf('dir.glb/model')).toBeNull();
    expect(MESH_EXTENSIONS).toBe('.stl, .3mf or .glb');
  });

  it('writes STL without colours and asks the coloured formats for theirs', async () => {
    expect(readStl(await meshFileBytes('stl', tet, null, 'tet')).triangles).toHaveLength(4);
    await expect(meshFileBytes('3mf', tet, null, 'tet')).rejects.toThrow(/needs its colours/);
  });
});
