/**
 * 3MF (src/io/three-mf.ts): the two-sphere mesh coloured by depth, written as a 3MF package and
 * read back by an independent reader — Python's zipfile and ElementTree (support/read_3mf.py),
 * the way a slicer finds the model through the package's relationships. The triangles are the
 * mesh's own (indices in range, closed and oriented), every corner names a colour of the colour
 * group, and the seed's corners carry the seed's colour, the image's a quarter turn on the wheel.
 */
import { spawnSync } from 'node:child_process';
import { mkdtempSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { unzipSync } from 'fflate';
import { afterAll, describe, expect, it } from 'vitest';
import type { Mesh } from '../../../nodes/geometry/space/marching-tetrahedra.ts';
import { threeMfModel, write3mf } from '../../../src/io/three-mf.ts';
import {
  colouredMesh,
  IMAGE_COLOUR,
  SEED_COLOUR,
  SEED_SIDE_X,
  unmatchedEdges,
} from '../../shader-gen/space/coloured-mesh.ts';

const READER = join(import.meta.dirname, 'support', 'read_3mf.py');
const hasPython = spawnSync('python3', ['--version']).status === 0;
const dir = mkdtempSync(join(tmpdir(), 'kleinflow-3mf-'));
afterAll(() => rmSync(dir, { recursive: true, force: true }));

interface Read3mf {
  contentTypes: Record<string, string>;
  modelTargets: string[];
  unit: string;
  objects: number;
  object: { id: string; pid: string; pindex: string };
  buildItems: string[];
  colorGroups: Record<string, string[]>;
  vertices: number[][];
  triangles: (number | null)[][];
}

function read3mf(bytes: Uint8Array): Read3mf {
  const path = join(dir, 'model.3mf');
  writeFileSync(path, bytes);
  const r = spawnSync('python3', [READER, path], { encoding: 'utf8', maxBuffer: 1 << 28 });
  if (r.status !== 0) throw new Error(r.stderr);
  return JSON.parse(r.stdout) as Read3mf;
}

/** As the writer sees the colour: float32 (0.9 is 229.4999… of 255 there, not 229.5). */
const hex = (c: readonly number[]) =>
  `#${c
    .map((v) =>
      Math.round(Math.fround(v) * 255)
        .toString(16)
        .padStart(2, '0')
        .toUpperCase(),
    )
    .join('')}`;

describe('write3mf', () => {
  it.skipIf(!hasPython)('reads back in Python as the closed mesh, each corner with its colour', async () => {
    const { mesh, colours } = await colouredMesh(16);
    const m = read3mf(write3mf(mesh, colours));
    expect(m.contentTypes.model).toBe('application/vnd.ms-package.3dmanufacturing-3dmodel+xml');
    expect(m.contentTypes.rels).toBe('application/vnd.openxmlformats-package.relationships+xml');
    expect(m.modelTargets).toEqual(['/3D/3dmodel.model']);
    expect(m.unit).toBe('millimeter');
    expect(m.buildItems).toEqual([m.object.id]);
    const palette = m.colorGroups[m.object.pid]!;
    expect(palette.length).toBeGreaterThanOrEqual(2);
    expect(new Set(palette).size).toBe(palette.length);
    // The vertices are the mesh's, to 9 significant digits.
    const n = mesh.positions.length / 3;
    expect(m.vertices.length).toBe(n);
    m.vertices.forEach((v, i) => {
      for (let k = 0; k < 3; k++) expect(v[k]).toBeCloseTo(mesh.positions[3 * i + k]!, 7);
    });
    // The triangles are the mesh's, closed and oriented, every corner's colour in the group.
    expect(m.triangles.length).toBe(mesh.triangles.length / 3);
    const indices = m.triangles.flatMap((t) => t.slice(0, 3) as number[]);
    expect(indices).toEqual([...mesh.triangles]);
    expect(indices.every((i) => i >= 0 && i < n)).toBe(true);
    expect(unmatchedEdges(indices)).toBe(0);
    const seedHex = hex(SEED_COLOUR);
    const imageHex = hex(IMAGE_COLOUR);
    let image = 0;
    for (const [v1, v2, v3, pid, ...p] of m.triangles) {
      expect(String(pid)).toBe(m.object.pid);
      [v1, v2, v3].forEach((v, corner) => {
        const colour = palette[p[corner]!];
        const onSeed = m.vertices[v!]![0]! < SEED_SIDE_X;
        expect(colour).toBe(onSeed ? seedHex : imageHex);
        if (!onSeed) image++;
      });
    }
    expect(image).toBeGreaterThan(0);
  });

  it('is a zip of the content types, the root relationship and the model', async () => {
    const tet: Mesh = {
      positions: Float64Array.from([0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1e-7]),
      triangles: Uint32Array.from([0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3]),
    };
    const colours = Float32Array.from([1, 0, 0, 1, 0, 0, 0, 0.5, 1, 1, 0, 0]);
    const files = unzipSync(write3mf(tet, colours));
    expect(Object.keys(files).sort()).toEqual(['3D/3dmodel.model', '[Content_Types].xml', '_rels/.rels']);
    const model = new TextDecoder().decode(files['3D/3dmodel.model']);
    expect(model).toBe(threeMfModel(tet, colours));
    // Two distinct colours, each once; corners point at them; numbers in 3MF's number syntax.
    expect(model.match(/<m:color color="#[0-9A-F]{6}"\/>/g)).toEqual([
      '<m:color color="#FF0000"/>',
      '<m:color color="#0080FF"/>',
    ]);
    expect(model).toContain('<triangle v1="0" v2="1" v3="3" pid="1" p1="0" p2="0" p3="0"/>');
    expect(model).toContain('<triangle v1="0" v2="2" v3="1" pid="1" p1="0" p2="1" p3="0"/>');
    expect(model).toContain('<vertex x="0" y="0" z="1e-7"/>');
    expect(() => threeMfModel(tet, colours.subarray(0, 9))).toThrow(/3 colours for 4 vertices/);
  });
});
