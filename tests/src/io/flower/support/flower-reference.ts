/**
 * An independent reading of a Flower preset for tests: the mirrors as Flower defines them, taken
 * straight from the JSON (not through the importer). Facts: a LineTwoPoints runs from the point
 * on its first input (p1) to the point on its second (p2); a LineMirror keeps the left side of
 * p1 → p2, `reverse` keeps the right; a CircleMirror inverts in the circle through three points;
 * a Point's position is posX/posY. Flower's tile: outside every circle, on the kept side of every line.
 */
type Raw = Record<string, unknown> & {
  id: string;
  name: string;
  sockets: { id: string; isOutput: boolean }[];
};
type V = [number, number];

export interface FlowerLineMirror {
  readonly p1: V;
  readonly p2: V;
  readonly reverse: boolean;
}
export interface FlowerCircleMirror {
  readonly c: V;
  readonly r: number;
}

export function flowerMirrors(json: { nodes: Raw[]; edges: { s1Id: string; s2Id: string }[] }) {
  const nodes = new Map<string, Raw>();
  for (const n of json.nodes) if (!nodes.has(n.id)) nodes.set(n.id, n);
  const socket = new Map<string, { node: Raw; ordinal: number; isOutput: boolean }>();
  for (const n of nodes.values()) {
    const count = { in: 0, out: 0 };
    for (const s of n.sockets)
      socket.set(s.id, { node: n, isOutput: s.isOutput, ordinal: s.isOutput ? count.out++ : count.in++ });
  }
  /** The node feeding input `ordinal` of `node`. */
  const feeding = (node: Raw, ordinal: number): Raw | undefined => {
    for (const e of json.edges) {
      const [a, b] = [socket.get(e.s1Id), socket.get(e.s2Id)];
      if (!a || !b) continue;
      const [out, inp] = a.isOutput ? [a, b] : [b, a];
      if (inp.node === node && inp.ordinal === ordinal && !inp.isOutput) return out.node;
    }
    return undefined;
  };
  const pos = (n: Raw | undefined): V => [n?.posX as number, n?.posY as number];
  const lines: FlowerLineMirror[] = [];
  const circles: FlowerCircleMirror[] = [];
  for (const n of nodes.values()) {
    if (n.name === 'LineMirror') {
      const line = feeding(n, 0);
      if (line)
        lines.push({ p1: pos(feeding(line, 0)), p2: pos(feeding(line, 1)), reverse: n.reverse === true });
    } else if (n.name === 'CircleMirror') {
      const circle = feeding(n, 0);
      if (circle)
        circles.push(circumcircle(pos(feeding(circle, 0)), pos(feeding(circle, 1)), pos(feeding(circle, 2))));
    }
  }
  return { lines, circles };
}

/** Circumcircle by the perpendicular-bisector equations 2(a−b)·c = |a|²−|b|², 2(a−d)·c = |a|²−|d|². */
function circumcircle(a: V, b: V, d: V): FlowerCircleMirror {
  const [p, q] = [2 * (a[0] - b[0]), 2 * (a[1] - b[1])];
  const [r, s] = [2 * (a[0] - d[0]), 2 * (a[1] - d[1])];
  const [u, v] = [
    a[0] ** 2 + a[1] ** 2 - b[0] ** 2 - b[1] ** 2,
    a[0] ** 2 + a[1] ** 2 - d[0] ** 2 - d[1] ** 2,
  ];
  const det = p * s - q * r;
  const c: V = [(u * s - q * v) / det, (p * v - u * r) / det];
  return { c, r: Math.hypot(a[0] - c[0], a[1] - c[1]) };
}

/** Unit normal pointing into the kept side of a Flower line mirror. */
export function keptNormal(m: FlowerLineMirror): V {
  const [dx, dy] = [m.p2[0] - m.p1[0], m.p2[1] - m.p1[1]];
  const len = Math.hypot(dx, dy);
  const left: V = [-dy / len, dx / len];
  return m.reverse ? [-left[0], -left[1]] : left;
}

/** Whether Flower would leave p uncoloured (n = 0): outside every circle, kept side of every line. */
export function inFlowerTile(mirrors: ReturnType<typeof flowerMirrors>, p: V): boolean {
  if (mirrors.circles.some(({ c, r }) => Math.hypot(p[0] - c[0], p[1] - c[1]) < r)) return false;
  return mirrors.lines.every((m) => {
    const n = keptNormal(m);
    return (p[0] - m.p1[0]) * n[0] + (p[1] - m.p1[1]) * n[1] >= 0;
  });
}
