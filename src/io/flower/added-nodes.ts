/**
 * The nodes a Flower import adds that Flower had no node for: the Time node that drives animated
 * values, the tile that colours like Flower (with every orbit seed wired into its `seeds`), and
 * the render node with every mirror wired in Flower's order (circles first: Flower tests them
 * before the lines).
 */
import type { Diagnostic } from '../../../nodes/core/diagnostics.ts';
import { toHex } from '../../../nodes/core/port-values.ts';
import type { GraphEdge, GraphNode } from '../../../nodes/graph/document.ts';
import { type FlowerGraph, type FlowerNode, note } from './format.ts';
import type { MappedNode } from './mapping.ts';
import { FLOWER_PALETTE_STEP, readFlowerPalette } from './palette.ts';

/** Flower's picture: hue 0.01 + 0.05(n − 1) for n reflections, 50 iterations, 20 samples. */
export const FLOWER_RENDER = { hueStart: 0.01, hueStep: 0.05, maxIterations: 50, samples: 20 } as const;
/** Flower's node-graph pixels → Kleinflow editor units (Kleinflow's nodes are larger). */
export const GRAPH_SPREAD = 1.5;

/** Flower tests every circle mirror first, then reflects in the line mirrors, each in file order. */
export function mirrorOrder(graph: FlowerGraph, mapped: ReadonlyMap<string, MappedNode>): FlowerNode[] {
  const of = (kind: 'circle' | 'line') => graph.nodes.filter((n) => mapped.get(n.id)?.mirror === kind);
  return [...of('circle'), ...of('line')];
}

/** One Time node drives every animated node (Flower's SinWave, CircularMotion) through its `t`. */
export function addTime(
  graph: FlowerGraph,
  mapped: ReadonlyMap<string, MappedNode>,
  ids: ReadonlyMap<string, string>,
  nodes: GraphNode[],
  edges: GraphEdge[],
): void {
  const animated = graph.nodes.filter((n) => mapped.get(n.id)?.timeInput);
  if (animated.length === 0) return;
  let id = 'T1';
  for (let k = 2; nodes.some((n) => n.id === id); k++) id = `T${k}`;
  const left = Math.min(...nodes.map((n) => n.position[0])) - 300;
  const top = Math.min(...animated.map((n) => n.y * GRAPH_SPREAD));
  nodes.push({ id, type: 'time', position: [left, Math.round(top)], params: {} });
  for (const fn of animated) {
    const to = { node: ids.get(fn.id)!, port: mapped.get(fn.id)!.timeInput! };
    edges.push({ id: `e${edges.length + 1}`, from: { node: id, port: 'time' }, to });
  }
}

/** Adds the tile (Flower's colouring, every seed) and the render node with every mirror, in Flower's order. */
export function addOutput(
  graph: FlowerGraph,
  mapped: ReadonlyMap<string, MappedNode>,
  ids: ReadonlyMap<string, string>,
  nodes: GraphNode[],
  edges: GraphEdge[],
  notes: Diagnostic[],
): void {
  const taken = new Set(nodes.map((n) => n.id));
  const fresh = (base: string) => {
    let id = base;
    for (let k = 2; taken.has(id); k++) id = `${base}-${k}`;
    taken.add(id);
    return id;
  };
  const right = Math.max(0, ...nodes.map((n) => n.position[0])) + 300;
  const middle = nodes.length ? nodes.reduce((s, n) => s + n.position[1], 0) / nodes.length : 0;
  const tileId = fresh('tile');
  const renderId = fresh('render');
  nodes.push({
    id: tileId,
    type: 'tile',
    position: [right, Math.round(middle + 220)],
    params: tileParams(graph, notes),
  });
  nodes.push({
    id: renderId,
    type: 'render',
    position: [right + 300, Math.round(middle)],
    params: { maxIterations: FLOWER_RENDER.maxIterations, samples: FLOWER_RENDER.samples },
  });
  edges.push({
    id: `e${edges.length + 1}`,
    from: { node: tileId, port: 'tile' },
    to: { node: renderId, port: 'tile' },
  });
  // Orbit seeds (Flower's OrbitSeed) are painted by the tile, in file order.
  for (const fn of graph.nodes.filter((n) => mapped.get(n.id)?.seed)) {
    edges.push({
      id: `e${edges.length + 1}`,
      from: { node: ids.get(fn.id)!, port: 'seed' },
      to: { node: tileId, port: 'seeds' },
    });
  }
  for (const fn of mirrorOrder(graph, mapped)) {
    edges.push({
      id: `e${edges.length + 1}`,
      from: { node: ids.get(fn.id)!, port: 'element' },
      to: { node: renderId, port: 'elements' },
    });
  }
}

/** Flower leaves the tile itself (n = 0) uncoloured, i.e. black: the tile fill does the same. */
export const FLOWER_TILE_FILL = '#000000';

/**
 * Depth-HSV with Flower's hues (hue 0.01 + 0.05(n − 1) = 0.96 + 0.05n mod 1), or its palette;
 * either way with the tile (depth 0) filled black.
 */
function tileParams(graph: FlowerGraph, notes: Diagnostic[]): Record<string, unknown> {
  return { ...colouringParams(graph, notes), fillTile: true, fill: FLOWER_TILE_FILL };
}

function colouringParams(graph: FlowerGraph, notes: Diagnostic[]): Record<string, unknown> {
  const hsv = {
    mode: 'depth-hsv',
    hueOffset: FLOWER_RENDER.hueStart - FLOWER_RENDER.hueStep + 1,
    hueStep: FLOWER_RENDER.hueStep,
    saturation: 1,
    value: 1,
  };
  const paletteNode = graph.nodes.find((n) => n.name === 'ColorPalettes');
  if (!paletteNode) return hsv;
  const read = readFlowerPalette(paletteNode, graph);
  if (!read.ok) {
    notes.push(
      note(`nodes[${paletteNode.index}]`, `${read.message}; Flower's rainbow colouring is used instead`),
    );
    return hsv;
  }
  const { a, b, c, d } = read.palette;
  if ([a, b, c].some((v) => v.some((x) => x < 0 || x > 1))) {
    notes.push(
      note(
        `nodes[${paletteNode.index}]`,
        'palette values outside 0–1 were clamped (the tile stores its palette as colours)',
      ),
    );
  }
  return { mode: 'cosine', step: FLOWER_PALETTE_STEP, a: toHex(a), b: toHex(b), c: toHex(c), d: toHex(d) };
}
