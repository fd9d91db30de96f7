/**
 * GLB (src/io/glb.ts): the two-sphere mesh coloured by depth passes Khronos' glTF validator with no
 * errors and reads back (with @gltf-transform/core) as the same closed triangles with COLOR_0 per
 * vertex: the seed's vertices the seed's colour, the image's a quarter turn on, in linear light.
 */
import { WebIO } from '@gltf-transform/core';
import { validateBytes } from 'gltf-validator';
import { describe, expect, it } from 'vitest';
import { srgbToLinear } from '../../../shader-gen/srgb.ts';
import { writeGlb } from '../../../src/io/glb.ts';
import {
  colouredMesh,
  IMAGE_COLOUR,
  SEED_COLOUR,
  SEED_SIDE_X,
  unmatchedEdges,
} from '../../shader-gen/space/coloured-mesh.ts';

describe('writeGlb', () => {
  it('passes the Khronos validator and reads back as the closed mesh with its vertex colours', async () => {
    const { mesh, colours } = await colouredMesh(16);
    const bytes = await writeGlb(mesh, colours, 'two spheres');
    const report = await validateBytes(bytes);
    expect(report.issues.messages.filter((m) => m.severity === 0)).toEqual([]);
    expect(report.issues.numErrors).toBe(0);
    expect(report.info?.totalTriangleCount).toBe(mesh.triangles.length / 3);

    const doc = await new WebIO().readBinary(bytes);
    const [node] = doc.getRoot().listNodes();
    expect(node!.getName()).toBe('two spheres');
    const primitive = node!.getMesh()!.listPrimitives()[0]!;
    expect(primitive.getMode()).toBe(4); // TRIANGLES
    const positions = primitive.getAttribute('POSITION')!.getArray()!;
    const colour = primitive.getAttribute('COLOR_0')!;
    expect(colour.getType()).toBe('VEC3');
    const rgb = colour.getArray()!;
    const indices = [...primitive.getIndices()!.getArray()!];
    expect(indices).toEqual([...mesh.triangles]);
    expect(unmatchedEdges(indices)).toBe(0);
    const n = positions.length / 3;
    expect(n).toBe(mesh.positions.length / 3);
    let image = 0;
    for (let v = 0; v < n; v++) {
      const onSeed = positions[3 * v]! < SEED_SIDE_X;
      if (!onSeed) image++;
      const want = (onSeed ? SEED_COLOUR : IMAGE_COLOUR).map(srgbToLinear);
      for (let k = 0; k < 3; k++) expect(rgb[3 * v + k]).toBeCloseTo(want[k]!, 5);
    }
    expect(image).toBeGreaterThan(0);
    // Kleinflow's z-up turned to glTF's y-up.
    const [x, , , w] = node!.getRotation();
    expect([x, w].map((c) => c * Math.SQRT2)).toEqual([expect.closeTo(-1, 9), expect.closeTo(1, 9)]);
  });

  it('refuses colours that do not match the vertices', async () => {
    const { mesh, colours } = await colouredMesh(6);
    await expect(writeGlb(mesh, colours.subarray(3))).rejects.toThrow(/colours for/);
  });
});
