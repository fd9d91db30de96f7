/**
 * Builds small graphs in the original Flower editor's JSON format for unit tests: nodes with
 * sockets (ids derived from the node id), edges naming socket ids in either order.
 */
type Socket = { id: string; name: string; isOutput: boolean; edgeOn: boolean };
export type FlowerNodeJson = { name: string; x: number; y: number; id: string; sockets: Socket[] } & Record<
  string,
  unknown
>;
export type FlowerEdgeJson = { id: string; name: string; s1Id: string; s2Id: string };

/** Socket layouts of Flower's node types (inputs first, in Flower's order, then outputs). */
const SOCKETS: Record<string, [string[], string[]]> = {
  Constant: [[], ['Float']],
  SinWave: [[], ['Float']],
  CircularMotion: [[], ['Point']],
  Point: [['Float', 'Float'], ['Point']],
  Vec3: [['Float', 'Float', 'Float'], ['Vec3']],
  LineTwoPoints: [['Point', 'Point'], ['Line']],
  LineMirror: [['Line'], ['Line']],
  CircleThreePoints: [['Point', 'Point', 'Point'], ['Circle']],
  CircleMirror: [['Circle'], ['Circle']],
  // No preset holds one, so its sockets are unknown: tests give layouts explicitly when they need them.
  OrbitSeed: [[], []],
  ColorPalettes: [['Vec3', 'Vec3', 'Vec3', 'Vec3'], []],
};

export const inSocket = (node: string, i: number) => `${node}-in${i}`;
export const outSocket = (node: string, i = 0) => `${node}-out${i}`;

/** A node with Flower's socket layout for its type, or `layout` ([input types, output types]). */
export function fnode(
  name: string,
  id: string,
  extra: Record<string, unknown> = {},
  layout?: [string[], string[]],
): FlowerNodeJson {
  const [ins, outs] = layout ?? SOCKETS[name] ?? [[], []];
  return {
    name,
    x: 10,
    y: 20,
    id,
    sockets: [
      ...ins.map((s, i) => ({ id: inSocket(id, i), name: s, isOutput: false, edgeOn: false })),
      ...outs.map((s, i) => ({ id: outSocket(id, i), name: s, isOutput: true, edgeOn: false })),
    ],
    ...extra,
  };
}

let edgeCount = 0;
/** An edge from `from`'s output to input `input` of `to`; `reversed` lists the input socket first. */
export function fedge(
  name: string,
  from: string,
  to: string,
  input: number,
  reversed = false,
): FlowerEdgeJson {
  const [a, b] = [outSocket(from), inSocket(to, input)];
  return { id: `edge${++edgeCount}`, name, s1Id: reversed ? b : a, s2Id: reversed ? a : b };
}

export const fpoint = (id: string, x: number, y: number) => fnode('Point', id, { posX: x, posY: y });

/** Two points, a line p1 → p2 and a mirror of it. */
export function lineMirror(id: string, p1: [number, number], p2: [number, number], reverse: boolean) {
  return {
    nodes: [
      fpoint(`${id}a`, ...p1),
      fpoint(`${id}b`, ...p2),
      fnode('LineTwoPoints', `${id}L`),
      fnode('LineMirror', id, { reverse }),
    ],
    edges: [
      fedge('Point', `${id}a`, `${id}L`, 0),
      fedge('Point', `${id}b`, `${id}L`, 1, true),
      fedge('Line', `${id}L`, id, 0),
    ],
  };
}

/** Three points, the circle through them and a mirror of it. */
export function circleMirror(id: string, pts: [number, number][]) {
  return {
    nodes: [
      ...pts.map((p, i) => fpoint(`${id}p${i}`, ...p)),
      fnode('CircleThreePoints', `${id}C`),
      fnode('CircleMirror', id),
    ],
    edges: [
      ...pts.map((_, i) => fedge('Point', `${id}p${i}`, `${id}C`, i, i === 1)),
      fedge('Circle', `${id}C`, id, 0),
    ],
  };
}

export function graph(...parts: { nodes: FlowerNodeJson[]; edges: FlowerEdgeJson[] }[]) {
  return { name: 'fixture', nodes: parts.flatMap((p) => p.nodes), edges: parts.flatMap((p) => p.edges) };
}
