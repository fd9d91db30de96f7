/**
 * Flower's ColorPalettes node → the tile's cosine palette. Flower colours a point reflected n times
 * with a + b·cos(2π(c·t + d)), t = 0.05(n − 1); Kleinflow's tile uses t = depth·step. With
 * step = 0.05 the two agree when d' = d − 0.05·c (cos(2π(c·0.05n + d − 0.05c))), taken modulo 1.
 * The palette vectors come from the Vec3 nodes wired into ColorPalettes (or its own saved values).
 */
import type { Color } from '../../../nodes/core/values.ts';
import type { FlowerGraph, FlowerNode } from './format.ts';

export const FLOWER_PALETTE_STEP = 0.05;

export interface FlowerPalette {
  readonly a: Color;
  readonly b: Color;
  readonly c: Color;
  readonly d: Color;
}

const finite = (v: unknown): v is number => typeof v === 'number' && Number.isFinite(v);

/** Three numbers saved on a Flower node, under whichever key names its version used. */
export function readVec3(raw: Readonly<Record<string, unknown>>, key?: string): Color | null {
  const candidates: unknown[] = key ? [raw[key]] : [raw.value, raw.values, raw.vec3];
  for (const c of candidates) {
    if (Array.isArray(c) && c.length >= 3 && c.slice(0, 3).every(finite)) return [c[0], c[1], c[2]];
    if (c && typeof c === 'object' && !Array.isArray(c)) {
      const o = c as Record<string, unknown>;
      if ([o.x, o.y, o.z].every(finite)) return [o.x as number, o.y as number, o.z as number];
    }
  }
  if (key) return null;
  for (const names of [
    ['valueX', 'valueY', 'valueZ'],
    ['value1', 'value2', 'value3'],
    ['r', 'g', 'b'],
  ]) {
    const v = names.map((n) => raw[n]);
    if (v.every(finite)) return v as unknown as Color;
  }
  return null;
}

/** The palette of a ColorPalettes node, or a message saying what could not be read. */
export function readFlowerPalette(
  node: FlowerNode,
  graph: FlowerGraph,
): { ok: true; palette: FlowerPalette } | { ok: false; message: string } {
  const byId = new Map(graph.nodes.map((n) => [n.id, n]));
  const out: Color[] = [];
  for (const [i, key] of ['a', 'b', 'c', 'd'].entries()) {
    const link = graph.links.find((l) => l.to === node.id && l.toInput === i);
    const source = link && byId.get(link.from);
    const v = source
      ? readVec3(source.raw)
      : (readVec3(node.raw, key) ?? readVec3(node.raw, `colorPalettes${key.toUpperCase()}`));
    if (!v)
      return { ok: false, message: `ColorPalettes "${node.id}": palette vector ${key} could not be read` };
    out.push(v);
  }
  const [a, b, c, d] = out;
  const shifted = d.map((di, k) => {
    const v = di - FLOWER_PALETTE_STEP * c[k];
    return v - Math.floor(v);
  }) as unknown as Color;
  return { ok: true, palette: { a, b, c, d: shifted } };
}
