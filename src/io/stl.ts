/**
 * Binary STL (the 3D printing format): an 80-byte header, the triangle count (uint32), then 50
 * bytes per triangle — the unit normal and three vertices as float32 x, y, z, and a uint16
 * attribute (0). Little-endian throughout. Vertices are anticlockwise seen from outside.
 */
import type { Mesh } from '../../nodes/geometry/space/marching-tetrahedra.ts';

const HEADER = 80;
const PER_TRIANGLE = 50;

/** The mesh as binary STL bytes; `header` (ASCII, cut to 80 bytes) names the source. */
export function writeStl(mesh: Mesh, header = 'Kleinflow mesh'): Uint8Array<ArrayBuffer> {
  const n = mesh.triangles.length / 3;
  const bytes = new Uint8Array(HEADER + 4 + n * PER_TRIANGLE);
  const view = new DataView(bytes.buffer);
  for (let i = 0; i < Math.min(HEADER, header.length); i++) bytes[i] = header.charCodeAt(i) & 0x7f;
  view.setUint32(HEADER, n, true);
  const p = mesh.positions;
  let at = HEADER + 4;
  for (let t = 0; t < n; t++) {
    const [a, b, c] = [0, 1, 2].map((v) => mesh.triangles[3 * t + v] * 3);
    // n = (b − a) × (c − a), normalised (a degenerate triangle gets 0, 0, 0).
    const u = [p[b] - p[a], p[b + 1] - p[a + 1], p[b + 2] - p[a + 2]];
    const w = [p[c] - p[a], p[c + 1] - p[a + 1], p[c + 2] - p[a + 2]];
    const nx = u[1] * w[2] - u[2] * w[1];
    const ny = u[2] * w[0] - u[0] * w[2];
    const nz = u[0] * w[1] - u[1] * w[0];
    const len = Math.hypot(nx, ny, nz) || 1;
    for (const v of [
      nx / len,
      ny / len,
      nz / len,
      p[a],
      p[a + 1],
      p[a + 2],
      p[b],
      p[b + 1],
      p[b + 2],
      p[c],
      p[c + 1],
      p[c + 2],
    ]) {
      view.setFloat32(at, v, true);
      at += 4;
    }
    view.setUint16(at, 0, true);
    at += 2;
  }
  return bytes;
}

export interface StlTriangle {
  readonly normal: readonly [number, number, number];
  readonly vertices: readonly [
    readonly [number, number, number],
    readonly [number, number, number],
    readonly [number, number, number],
  ];
}

/** Reads binary STL bytes back (for tests and checks); throws on a size that does not match the count. */
export function readStl(bytes: Uint8Array): { header: string; triangles: StlTriangle[] } {
  if (bytes.length < HEADER + 4) throw new Error('not a binary STL: shorter than its 84-byte header');
  const view = new DataView(bytes.buffer, bytes.byteOffset, bytes.byteLength);
  const n = view.getUint32(HEADER, true);
  if (bytes.length !== HEADER + 4 + n * PER_TRIANGLE)
    throw new Error(
      `not a binary STL: ${n} triangles need ${HEADER + 4 + n * PER_TRIANGLE} bytes, got ${bytes.length}`,
    );
  const header = String.fromCharCode(...bytes.subarray(0, HEADER)).replace(/\0+$/, '');
  const triangles: StlTriangle[] = [];
  for (let t = 0; t < n; t++) {
    const base = HEADER + 4 + t * PER_TRIANGLE;
    const f = (i: number) => view.getFloat32(base + 4 * i, true);
    const v3 = (i: number) => [f(i), f(i + 1), f(i + 2)] as const;
    triangles.push({ normal: v3(0), vertices: [v3(3), v3(6), v3(9)] });
  }
  return { header, triangles };
}
