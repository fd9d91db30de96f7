/** Small builders for hand-written test documents (the JSON shape of docs/architecture.md). */
import type { GraphDoc, GraphEdge, GraphNode } from '../../../nodes/graph/document.ts';
import { registry } from '../../../nodes/types/index.ts';

/** A node of the type's current version (written only past 1, as the editor writes it). */
export function node(id: string, type: string, params: Record<string, unknown> = {}): GraphNode {
  const version = registry.get(type)?.version ?? 1;
  return { id, type, position: [0, 0], params, ...(version > 1 ? { version } : {}) };
}

/** An edge written as `edge('e1', 'p1.point', 'c1.center')`. */
export function edge(id: string, from: string, to: string): GraphEdge {
  const [fn, fp] = from.split('.');
  const [tn, tp] = to.split('.');
  return { id, from: { node: fn, port: fp }, to: { node: tn, port: tp } };
}

export function doc(nodes: GraphNode[], edges: GraphEdge[] = []): GraphDoc {
  return {
    format: 'kleinflow',
    version: 1,
    meta: { title: 'test' },
    nodes,
    edges,
    view: { center: [0, 0], scale: 4 },
  };
}

/** Deterministic shuffle (mulberry32) so permutation tests are reproducible. */
export function shuffled<T>(items: readonly T[], seed: number): T[] {
  let a = seed >>> 0;
  const rand = () => {
    a = (a + 0x6d2b79f5) >>> 0;
    let t = a;
    t = Math.imul(t ^ (t >>> 15), t | 1);
    t ^= t + Math.imul(t ^ (t >>> 7), t | 61);
    return ((t ^ (t >>> 14)) >>> 0) / 4294967296;
  };
  const out = [...items];
  for (let i = out.length - 1; i > 0; i--) {
    const j = Math.floor(rand() * (i + 1));
    [out[i], out[j]] = [out[j], out[i]];
  }
  return out;
}
