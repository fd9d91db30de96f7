/**
 * Tidy layout: nodes in columns by their depth in the graph (sources left, render right, see
 * layers.ts), stacked without overlap. Used when a loaded document's nodes overlap, and by the Tidy button.
 */
import type { InputSpec, NodeDef } from '../../nodes/core/define-node.ts';
import type { NodeRegistry } from '../../nodes/core/registry.ts';
import type { GraphDoc, GraphNode } from '../../nodes/graph/document.ts';
import { nodeDef } from '../../nodes/graph/group-def.ts';
import { layers } from './layers.ts';
import { nodeFields } from './node-fields.ts';
import { hasInlineEditor } from './widgets/inline-editor.ts';

export interface Size {
  readonly width: number;
  readonly height: number;
}

/** How the graph is framed: never zoomed in past 1, nor out below where node text stays readable. */
export const FIT_VIEW = { padding: 0.08, maxZoom: 1, minZoom: 0.72 } as const;

/** Node width and row heights of the node component (src/styles/node.css). */
export const NODE_WIDTH = 236;
const HEADER = 31;
const BODY_PADDING = 11;
const ROW = 24;
const READOUT = 27;
const GAP_X = 80;
const GAP_Y = 28;

/** Rows an input takes: a line, circle, sphere or plane editor is two rows, everything else one. */
function inputRows(spec: InputSpec, value: unknown, connected: boolean): number {
  const twoRows =
    spec.type === 'line' || spec.type === 'circle' || spec.type === 'sphere' || spec.type === 'plane';
  return twoRows && !connected && hasInlineEditor(spec, value) ? 2 : 1;
}

/** The height the node component will have, estimated from its declaration. */
export function estimateSize(
  node: GraphNode,
  def: NodeDef | undefined,
  connected: ReadonlySet<string>,
): Size {
  if (!def) return { width: NODE_WIDTH, height: HEADER + BODY_PADDING + ROW * 3 };
  // The rows the node shows in its set-up, with its "More" section closed (one toggle row).
  const { main, more } = nodeFields(def, node.params, connected);
  let rows = Object.keys(def.outputs).length + (more.length > 0 ? 1 : 0);
  for (const f of main)
    rows += f.kind === 'input' ? inputRows(f.spec, node.params[f.name], connected.has(f.name)) : 1;
  // Most nodes show a read-out; reserving its row for all keeps the estimate on the safe side.
  return { width: NODE_WIDTH, height: HEADER + BODY_PADDING + rows * ROW + READOUT };
}

type SizeOf = (node: GraphNode) => Size;

export function sizer(doc: GraphDoc, registry: NodeRegistry): SizeOf {
  const connected = new Map<string, Set<string>>();
  for (const e of doc.edges) connected.set(e.to.node, (connected.get(e.to.node) ?? new Set()).add(e.to.port));
  return (node) => estimateSize(node, nodeDef(registry, node), connected.get(node.id) ?? new Set());
}

type Box = { readonly x: number; readonly y: number } & Size;

const boxOf = (node: GraphNode, size: SizeOf): Box => ({
  x: node.position[0],
  y: node.position[1],
  ...size(node),
});
const intersect = (a: Box, b: Box) =>
  a.x < b.x + b.width && b.x < a.x + a.width && a.y < b.y + b.height && b.y < a.y + a.height;

/** Whether any two nodes' boxes intersect. */
export function nodesOverlap(doc: GraphDoc, size: SizeOf): boolean {
  const boxes = doc.nodes.map((n) => boxOf(n, size));
  for (let i = 0; i < boxes.length; i++) {
    for (let j = i + 1; j < boxes.length; j++) if (intersect(boxes[i], boxes[j])) return true;
  }
  return false;
}

/**
 * How far right new nodes `placed` must move so they cover no node of `doc`: 0 where they are
 * clear, else one node width and a gap at a time, as often as needed. A node added twice from the
 * Add node button (no pointer position) would otherwise land exactly on the one before, and a paste
 * under the pointer could hide the node it lands on (and its header, the handle to drag it by).
 */
export function clearShift(doc: GraphDoc, placed: readonly GraphNode[], size: SizeOf): number {
  const others = doc.nodes.map((n) => boxOf(n, size));
  const own = placed.map((n) => boxOf(n, size));
  let dx = 0;
  while (own.some((a) => others.some((b) => intersect({ ...a, x: a.x + dx }, b)))) dx += NODE_WIDTH + GAP_X;
  return dx;
}

/** Where `node` goes so it covers no node of `doc` (see clearShift). */
export function clearSpot(doc: GraphDoc, node: GraphNode, size: SizeOf): [number, number] {
  return [node.position[0] + clearShift(doc, [node], size), node.position[1]];
}

/**
 * New positions: the columns and their order from layers.ts (sources left, Render alone on the
 * right, wires one column long where they can be, few crossings), stacked from the top-left of the
 * current layout.
 */
export function tidyPositions(
  doc: GraphDoc,
  size: SizeOf,
  registry: NodeRegistry,
): { nodeId: string; position: [number, number] }[] {
  if (doc.nodes.length === 0) return [];
  // An output node declares no outputs: Render, the picture's node.
  const isOutput = (n: GraphNode) => {
    const def = nodeDef(registry, n);
    return def !== undefined && Object.keys(def.outputs).length === 0;
  };
  const left = Math.min(...doc.nodes.map((n) => n.position[0]));
  const top = Math.min(...doc.nodes.map((n) => n.position[1]));
  const moves: { nodeId: string; position: [number, number] }[] = [];
  layers(doc, isOutput).columns.forEach((nodes, d) => {
    let y = top;
    for (const n of nodes) {
      moves.push({ nodeId: n.id, position: [left + d * (NODE_WIDTH + GAP_X), y] });
      y += size(n).height + GAP_Y;
    }
  });
  return moves;
}

/** The document with a tidy layout when its nodes overlap; otherwise the same document. */
export function tidyIfOverlapping(doc: GraphDoc, registry: NodeRegistry): GraphDoc {
  const size = sizer(doc, registry);
  if (!nodesOverlap(doc, size)) return doc;
  const to = new Map(tidyPositions(doc, size, registry).map((m) => [m.nodeId, m.position]));
  return { ...doc, nodes: doc.nodes.map((n) => ({ ...n, position: to.get(n.id) ?? n.position })) };
}
