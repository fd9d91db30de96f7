/**
 * The coloured mesh as binary glTF 2.0 (GLB), the format 3D viewers read (paper Fig. 36; docs/math-3d.md
 * "Coloured mesh (paper Fig. 36)"): one indexed triangle primitive with POSITION, COLOR_0 (per vertex,
 * linear RGB as glTF requires — the sRGB colours are converted) and a plain white, rough material
 * that the vertex colours multiply. No NORMAL: viewers then shade the triangles flat, as the spec
 * says. Kleinflow's z is up, glTF's y: the node turns the mesh −90° about x, the vertices are the
 * mesh's own — in metres, glTF's unit: mesh-file.ts scales them to the print size first. The
 * container is written by @gltf-transform/core (a maintained glTF library).
 */
import { Document, WebIO } from '@gltf-transform/core';
import type { Mesh } from '../../nodes/geometry/space/marching-tetrahedra.ts';
import { srgbToLinear } from '../../shader-gen/srgb.ts';

/** −90° about x: (x, y, z) → (x, z, −y), so Kleinflow's up (z) is glTF's up (y). */
const Z_UP_TO_Y_UP: [number, number, number, number] = [-Math.SQRT1_2, 0, 0, Math.SQRT1_2];

/** GLB bytes of `mesh` with sRGB `colours` (3 floats in [0, 1] per vertex); `name` names the node. */
export async function writeGlb(
  mesh: Mesh,
  colours: Float32Array,
  name = 'Kleinflow mesh',
): Promise<Uint8Array<ArrayBuffer>> {
  if (colours.length !== mesh.positions.length)
    throw new Error(`${colours.length / 3} colours for ${mesh.positions.length / 3} vertices`);
  const doc = new Document();
  doc.getRoot().getAsset().generator = 'Kleinflow';
  const buffer = doc.createBuffer();
  const linear = colours.map(srgbToLinear);
  const position = doc.createAccessor('position').setType('VEC3').setArray(new Float32Array(mesh.positions));
  const colour = doc.createAccessor('colour').setType('VEC3').setArray(linear);
  const indices = doc.createAccessor('indices').setType('SCALAR').setArray(new Uint32Array(mesh.triangles));
  for (const a of [position, colour, indices]) a.setBuffer(buffer);
  const material = doc.createMaterial('vertex colours').setRoughnessFactor(1).setMetallicFactor(0);
  const primitive = doc
    .createPrimitive()
    .setAttribute('POSITION', position)
    .setAttribute('COLOR_0', colour)
    .setIndices(indices)
    .setMaterial(material);
  const node = doc
    .createNode(name)
    .setMesh(doc.createMesh(name).addPrimitive(primitive))
    .setRotation(Z_UP_TO_Y_UP);
  doc.getRoot().setDefaultScene(doc.createScene(name).addChild(node));
  // A copy typed as ArrayBuffer-backed, as Blob and writeFile take it.
  return new Uint8Array(await new WebIO().writeBinary(doc));
}
