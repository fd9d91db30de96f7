/**
 * The mesh formats by extension (src/io/mesh-file.ts): any case, the last extension only, STL
 * without colours; a print size scales every format to the same physical size (STL and 3MF in
 * millimetres, GLB in metres) and leaves the triangles and the colours as they were.
 */
import { WebIO } from '@gltf-transform/core';
import { unzipSync } from 'fflate';
import { describe, expect, it } from 'vitest';
import type { Mesh } from '../../../nodes/geometry/space/marching-tetrahedra.ts';
import { MESH_EXTENSIONS, meshFileBytes, meshFormatOf } from '../../../src/io/mesh-file.ts';
import { meshExtent, millimetresPerUnit } from '../../../src/io/print-size.ts';
import { readStl } from '../../../src/io/stl.ts';
import { colouredMesh } from '../../shader-gen/space/coloured-mesh.ts';

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

  it('scales STL and 3MF to millimetres and GLB to metres, the triangles and colours unchanged', async () => {
    const { mesh, colours } = await colouredMesh(12);
    const s = millimetresPerUnit(meshExtent(mesh), 60);
    expect(Math.max(...meshExtent(mesh)) * s).toBeCloseTo(60, 9);
    const p = mesh.positions;

    const stl = readStl(await meshFileBytes('stl', mesh, null, 'two spheres', s)).triangles;
    expect(stl).toHaveLength(mesh.triangles.length / 3);
    for (const [t, { vertices }] of stl.entries())
      for (const [corner, v] of vertices.entries())
        for (let a = 0; a < 3; a++)
          expect(v[a]).toBeCloseTo(s * p[3 * mesh.triangles[3 * t + corner]! + a]!, 4);

    const glb = await new WebIO().readBinary(await meshFileBytes('glb', mesh, colours, 'two spheres', s));
    const primitive = glb.getRoot().listMeshes()[0]!.listPrimitives()[0]!;
    const position = primitive.getAttribute('POSITION')!;
    for (const [i, v] of position.getArray()!.entries()) expect(v).toBeCloseTo((s / 1000) * p[i]!, 7);
    // glTF's accessor bounds: the longest side is 0.06 m.
    const [lo, hi] = [position.getMin([]), position.getMax([])];
    expect(Math.max(...hi.map((v, a) => v - lo[a]!))).toBeCloseTo(0.06, 6);
    expect([...primitive.getIndices()!.getArray()!]).toEqual([...mesh.triangles]);

    const model = async (mmPerUnit: number) =>
      new TextDecoder().decode(
        unzipSync(await meshFileBytes('3mf', mesh, colours, 'two spheres', mmPerUnit))['3D/3dmodel.model'],
      );
    const [scaled, unit] = [await model(s), await model(1)];
    const lines = (text: string, tag: RegExp) => text.split('\n').filter((l) => tag.test(l));
    // Same colour group and the same triangles with the same corner colours; only the vertices move.
    expect(lines(scaled, /<m:color |<triangle /)).toEqual(lines(unit, /<m:color |<triangle /));
    const xs = (text: string) => lines(text, /<vertex /).map((l) => Number(/x="([^"]+)"/.exec(l)![1]));
    const [xScaled, xUnit] = [xs(scaled), xs(unit)];
    expect(xScaled).toHaveLength(mesh.positions.length / 3);
    for (const [i, x] of xScaled.entries()) expect(x).toBeCloseTo(s * xUnit[i]!, 5);
  });
});
