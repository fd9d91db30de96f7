/** Checks on triangle meshes shared by the mesh tests: edge counts, orientation, point inside by ray parity. */
import type { Mesh } from '../../../../nodes/geometry/space/marching-tetrahedra.ts';
import type { Vec3 } from '../../../../nodes/geometry/space/vec3.ts';

/**
 * Every directed edge a→b of the triangles, counted. Closed and consistently oriented means each
 * directed edge occurs exactly once and its reverse exactly once (so every undirected edge is in
 * exactly two triangles, which traverse it in opposite directions).
 */
export function edgeProblems(m: Mesh): string[] {
  const directed = new Map<string, number>();
  for (let t = 0; t < m.triangles.length; t += 3)
    for (let e = 0; e < 3; e++) {
      const key = `${m.triangles[t + e]}>${m.triangles[t + ((e + 1) % 3)]}`;
      directed.set(key, (directed.get(key) ?? 0) + 1);
    }
  const bad: string[] = [];
  for (const [key, n] of directed) {
    const [a, b] = key.split('>');
    if (n !== 1) bad.push(`edge ${key} used ${n} times in one direction`);
    if (directed.get(`${b}>${a}`) !== 1) bad.push(`edge ${key} has no single opposite`);
  }
  return bad;
}

/**
 * Whether p is inside the closed mesh: the parity of crossings of a ray from p (Möller–Trumbore),
 * along a fixed irrational-ish direction so that it misses edges and vertices.
 */
export function insideMesh(m: Mesh, p: Vec3): boolean {
  const d: Vec3 = [0.5773, 0.6123, 0.5402];
  const P = m.positions;
  let crossings = 0;
  for (let t = 0; t < m.triangles.length; t += 3) {
    const a = m.triangles[t] * 3;
    const b = m.triangles[t + 1] * 3;
    const c = m.triangles[t + 2] * 3;
    const e1 = [P[b] - P[a], P[b + 1] - P[a + 1], P[b + 2] - P[a + 2]];
    const e2 = [P[c] - P[a], P[c + 1] - P[a + 1], P[c + 2] - P[a + 2]];
    const h = [d[1] * e2[2] - d[2] * e2[1], d[2] * e2[0] - d[0] * e2[2], d[0] * e2[1] - d[1] * e2[0]];
    const det = e1[0] * h[0] + e1[1] * h[1] + e1[2] * h[2];
    if (Math.abs(det) < 1e-15) continue;
    const s = [p[0] - P[a], p[1] - P[a + 1], p[2] - P[a + 2]];
    const u = (s[0] * h[0] + s[1] * h[1] + s[2] * h[2]) / det;
    if (u < 0 || u > 1) continue;
    const q = [s[1] * e1[2] - s[2] * e1[1], s[2] * e1[0] - s[0] * e1[2], s[0] * e1[1] - s[1] * e1[0]];
    const v = (d[0] * q[0] + d[1] * q[1] + d[2] * q[2]) / det;
    if (v < 0 || u + v > 1) continue;
    const dist = (e2[0] * q[0] + e2[1] * q[1] + e2[2] * q[2]) / det;
    if (dist > 0) crossings++;
  }
  return crossings % 2 === 1;
}
