/**
 * The original Flower editor's JSON (soma-arc/Flower): `{ name?, nodes: [...], edges: [...] }`.
 * A node is `{ name, x, y, id, sockets: [{ id, name, isOutput, edgeOn }], ...per-type values }`
 * (x, y: its place in the node graph; a Point's position is posX/posY). An edge is
 * `{ id, name, s1Id, s2Id }` naming two socket ids in EITHER order (one output, one input).
 * Flower's exporter repeats a node once per incoming edge (topological-sort artefact), so the same
 * id can appear several times. This module reads that shape into a clean graph with notes.
 */
import type { Diagnostic } from '../../../nodes/core/diagnostics.ts';
import { diag } from '../../../nodes/core/diagnostics.ts';

export interface FlowerSocket {
  readonly id: string;
  readonly name: string;
  readonly isOutput: boolean;
}

export interface FlowerNode {
  readonly id: string;
  readonly name: string;
  /** Place in Flower's node graph (pixels, y down). */
  readonly x: number;
  readonly y: number;
  readonly sockets: readonly FlowerSocket[];
  /** The whole JSON entry, for per-type values (posX, reverse, period, …). */
  readonly raw: Readonly<Record<string, unknown>>;
  /** Index of the first entry with this id in the file's `nodes` (for paths in notes). */
  readonly index: number;
}

/** A resolved edge: output socket `fromOutput` (index among the node's outputs) → input `toInput`. */
export interface FlowerLink {
  readonly from: string;
  readonly fromOutput: number;
  readonly to: string;
  readonly toInput: number;
  readonly name: string;
  readonly index: number;
}

export interface FlowerGraph {
  readonly name: string | undefined;
  readonly nodes: readonly FlowerNode[];
  readonly links: readonly FlowerLink[];
  readonly notes: Diagnostic[];
}

const isObject = (v: unknown): v is Record<string, unknown> =>
  typeof v === 'object' && v !== null && !Array.isArray(v);

/** Shape test: a `nodes` array whose entries have a string `name` and a `sockets` array. */
export function isFlowerDocument(json: unknown): boolean {
  if (!isObject(json) || 'format' in json || !Array.isArray(json.nodes)) return false;
  if (json.edges !== undefined && !Array.isArray(json.edges)) return false;
  return (
    json.nodes.length > 0 &&
    json.nodes.every((n) => isObject(n) && typeof n.name === 'string' && Array.isArray(n.sockets))
  );
}

/** How notes name a Flower node: `Point "16e8…"`. */
export const named = (node: FlowerNode) => `${node.name} "${node.id}"`;

export const finite = (v: unknown): v is number => typeof v === 'number' && Number.isFinite(v);

/** The first of `keys` saved on the node as a finite number, with the key it was found under. */
export function pickEntry(node: FlowerNode, ...keys: string[]): { key: string; value: number } | undefined {
  for (const key of keys) {
    const value = node.raw[key];
    if (finite(value)) return { key, value };
  }
  return undefined;
}

/** The first of `keys` saved on the node as a finite number. */
export const pick = (node: FlowerNode, ...keys: string[]): number | undefined =>
  pickEntry(node, ...keys)?.value;

/**
 * The first of the point `names` saved on the node: `name: [x, y]`, `name: { x, y }`, or the pair
 * `nameX`, `nameY` (as a Point's posX/posY), with the field(s) it was read from.
 */
export function pickPoint(
  node: FlowerNode,
  ...names: string[]
): { key: string; value: [number, number] } | undefined {
  for (const name of names) {
    const v = node.raw[name];
    if (Array.isArray(v) && v.length === 2 && finite(v[0]) && finite(v[1]))
      return { key: name, value: [v[0], v[1]] };
    if (isObject(v) && finite(v.x) && finite(v.y)) return { key: name, value: [v.x, v.y] };
    const [x, y] = [node.raw[`${name}X`], node.raw[`${name}Y`]];
    if (finite(x) && finite(y)) return { key: `${name}X/${name}Y`, value: [x, y] };
  }
  return undefined;
}

/** A KF502 import note at a path of the Flower file. */
export const note = (path: string, text: string): Diagnostic => diag('importNote', { path }, text);
const num = (v: unknown, fallback: number) => (typeof v === 'number' && Number.isFinite(v) ? v : fallback);

function readSockets(raw: unknown[], path: string, notes: Diagnostic[]): FlowerSocket[] {
  const out: FlowerSocket[] = [];
  raw.forEach((s, i) => {
    if (
      isObject(s) &&
      typeof s.id === 'string' &&
      typeof s.name === 'string' &&
      typeof s.isOutput === 'boolean'
    )
      out.push({ id: s.id, name: s.name, isOutput: s.isOutput });
    else notes.push(note(`${path}.sockets[${i}]`, 'a socket without id, name or isOutput was ignored'));
  });
  return out;
}

/** Reads nodes (first entry per id wins) and resolves every edge to output → input. */
export function readFlowerGraph(json: Record<string, unknown>): FlowerGraph {
  const notes: Diagnostic[] = [];
  const nodes = new Map<string, FlowerNode>();
  const rawNodes = json.nodes as unknown[];
  rawNodes.forEach((n, index) => {
    const path = `nodes[${index}]`;
    if (!isObject(n) || typeof n.name !== 'string' || !Array.isArray(n.sockets)) {
      notes.push(note(path, 'an entry that is not a Flower node (no name or sockets) was skipped'));
      return;
    }
    const id = typeof n.id === 'string' || typeof n.id === 'number' ? String(n.id) : `#${index}`;
    const seen = nodes.get(id);
    if (seen) {
      // Flower's exporter repeats nodes; identical copies are harmless, different ones are not.
      if (JSON.stringify(rawNodes[seen.index]) !== JSON.stringify(n)) {
        notes.push(
          note(
            path,
            `node "${id}" appears again with different data; the first entry (nodes[${seen.index}]) is used`,
          ),
        );
      }
      return;
    }
    const sockets = readSockets(n.sockets, path, notes);
    nodes.set(id, { id, name: n.name, x: num(n.x, 0), y: num(n.y, 0), sockets, raw: n, index });
  });

  const socketOwner = new Map<string, { node: FlowerNode; socket: FlowerSocket; ordinal: number }>();
  for (const node of nodes.values()) {
    let ins = 0;
    let outs = 0;
    for (const socket of node.sockets) {
      const ordinal = socket.isOutput ? outs++ : ins++;
      if (!socketOwner.has(socket.id)) socketOwner.set(socket.id, { node, socket, ordinal });
    }
  }

  const links: FlowerLink[] = [];
  const takenInputs = new Set<string>();
  /** The edge as output → input, or why it cannot be used. */
  const resolve = (e: unknown, index: number): FlowerLink | string => {
    if (!isObject(e)) return 'an edge entry that is not an object was skipped';
    const a = socketOwner.get(String(e.s1Id));
    const b = socketOwner.get(String(e.s2Id));
    if (!a || !b) return `edge names socket "${String(!a ? e.s1Id : e.s2Id)}", which no node has; skipped`;
    if (a.socket.isOutput === b.socket.isOutput) {
      const kind = a.socket.isOutput ? 'outputs' : 'inputs';
      return `edge joins two ${kind} (${a.node.name} and ${b.node.name}); skipped`;
    }
    const [out, inp] = a.socket.isOutput ? [a, b] : [b, a];
    if (out.socket.name !== inp.socket.name) {
      return `edge joins a ${out.socket.name} output to a ${inp.socket.name} input; skipped`;
    }
    if (takenInputs.has(inp.socket.id)) {
      return `input ${inp.ordinal + 1} of ${inp.node.name} "${inp.node.id}" has several edges; the first is used`;
    }
    takenInputs.add(inp.socket.id);
    const name = out.socket.name;
    return { from: out.node.id, fromOutput: out.ordinal, to: inp.node.id, toInput: inp.ordinal, name, index };
  };
  const rawEdges = Array.isArray(json.edges) ? json.edges : [];
  rawEdges.forEach((e, index) => {
    const link = resolve(e, index);
    if (typeof link === 'string') notes.push(note(`edges[${index}]`, link));
    else links.push(link);
  });
  return {
    name: typeof json.name === 'string' ? json.name : undefined,
    nodes: [...nodes.values()],
    links,
    notes,
  };
}
