/**
 * The coloured mesh as 3MF, the format full-colour printers and slicers read (3MF Core
 * Specification 1.3 with the Materials and Properties Extension 1.2; paper Fig. 36; docs/math-3d.md
 * "Coloured mesh (paper Fig. 36)"). A 3MF file is a zip (an OPC package) of three parts:
 *   [Content_Types].xml  the MIME types of the .rels and .model parts,
 *   _rels/.rels          the relationship naming 3D/3dmodel.model as the 3D model,
 *   3D/3dmodel.model     one mesh object: <vertices>, <triangles> (v1 v2 v3 anticlockwise seen from
 *                        outside, as 3MF requires), and an <m:colorgroup> of the distinct colours
 *                        (#RRGGBB, sRGB as the extension says); each triangle names the colour of
 *                        each of its corners (pid, p1 p2 p3), which readers blend across it.
 * Units are millimetres (the 3MF default): the vertices come scaled to the print size
 * (print-size.ts, via mesh-file.ts), one scene unit = 1 mm without one, as in the STL.
 */
import { strToU8, zipSync } from 'fflate';
import type { Mesh } from '../../nodes/geometry/space/marching-tetrahedra.ts';

const CORE = 'http://schemas.microsoft.com/3dmanufacturing/core/2015/02';
const MATERIAL = 'http://schemas.microsoft.com/3dmanufacturing/material/2015/02';
/** The ids of the colour group and of the object in the model's resources. */
const COLOURS_ID = 1;
const OBJECT_ID = 2;

const CONTENT_TYPES = `<?xml version="1.0" encoding="UTF-8"?>
<Types xmlns="http://schemas.openxmlformats.org/package/2006/content-types">
  <Default Extension="rels" ContentType="application/vnd.openxmlformats-package.relationships+xml"/>
  <Default Extension="model" ContentType="application/vnd.ms-package.3dmanufacturing-3dmodel+xml"/>
</Types>
`;

const RELS = `<?xml version="1.0" encoding="UTF-8"?>
<Relationships xmlns="http://schemas.openxmlformats.org/package/2006/relationships">
  <Relationship Target="/3D/3dmodel.model" Id="rel0" Type="http://schemas.microsoft.com/3dmanufacturing/2013/01/3dmodel"/>
</Relationships>
`;

/** A [0, 1] channel as two hex digits. */
const hex2 = (c: number) =>
  Math.round(Math.min(1, Math.max(0, c)) * 255)
    .toString(16)
    .padStart(2, '0')
    .toUpperCase();

/** A coordinate to 9 significant digits (more than float32 holds), in 3MF's ST_Number syntax. */
const num = (v: number) => String(Number(v.toPrecision(9)));

/** The 3D/3dmodel.model text of `mesh` with sRGB `colours` (3 floats in [0, 1] per vertex). */
export function threeMfModel(mesh: Mesh, colours: Float32Array): string {
  const n = mesh.positions.length / 3;
  if (colours.length !== 3 * n) throw new Error(`${colours.length / 3} colours for ${n} vertices`);
  // The distinct #RRGGBB colours, and each vertex's index among them.
  const index = new Map<string, number>();
  const vertexColour = new Uint32Array(n);
  for (let v = 0; v < n; v++) {
    const key = `#${hex2(colours[3 * v]!)}${hex2(colours[3 * v + 1]!)}${hex2(colours[3 * v + 2]!)}`;
    let i = index.get(key);
    if (i === undefined) {
      i = index.size;
      index.set(key, i);
    }
    vertexColour[v] = i;
  }
  const out: string[] = [
    '<?xml version="1.0" encoding="UTF-8"?>',
    `<model unit="millimeter" xml:lang="en-US" xmlns="${CORE}" xmlns:m="${MATERIAL}">`,
    '  <metadata name="Application">Kleinflow</metadata>',
    '  <resources>',
    `    <m:colorgroup id="${COLOURS_ID}">`,
  ];
  for (const key of index.keys()) out.push(`      <m:color color="${key}"/>`);
  out.push(
    '    </m:colorgroup>',
    `    <object id="${OBJECT_ID}" type="model" pid="${COLOURS_ID}" pindex="0">`,
    '      <mesh>',
    '        <vertices>',
  );
  const p = mesh.positions;
  for (let v = 0; v < n; v++)
    out.push(`          <vertex x="${num(p[3 * v]!)}" y="${num(p[3 * v + 1]!)}" z="${num(p[3 * v + 2]!)}"/>`);
  out.push('        </vertices>', '        <triangles>');
  const t = mesh.triangles;
  for (let i = 0; i < t.length; i += 3) {
    const [a, b, c] = [t[i]!, t[i + 1]!, t[i + 2]!];
    out.push(
      `          <triangle v1="${a}" v2="${b}" v3="${c}" pid="${COLOURS_ID}" p1="${vertexColour[a]}" p2="${vertexColour[b]}" p3="${vertexColour[c]}"/>`,
    );
  }
  out.push(
    '        </triangles>',
    '      </mesh>',
    '    </object>',
    '  </resources>',
    '  <build>',
    `    <item objectid="${OBJECT_ID}"/>`,
    '  </build>',
    '</model>',
    '',
  );
  return out.join('\n');
}

/** The 3MF package (zip bytes) of `mesh` with sRGB `colours` per vertex. */
export function write3mf(mesh: Mesh, colours: Float32Array): Uint8Array<ArrayBuffer> {
  const zip = zipSync({
    '[Content_Types].xml': strToU8(CONTENT_TYPES),
    '_rels/.rels': strToU8(RELS),
    '3D/3dmodel.model': strToU8(threeMfModel(mesh, colours)),
  });
  // fflate's bytes are ArrayBuffer-backed; the type says so for Blob.
  return new Uint8Array(zip.buffer, zip.byteOffset, zip.byteLength);
}
