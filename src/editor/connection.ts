/**
 * Connection rules of the graph editor, by port type (the one table in nodes/core/ports.ts):
 * which wires may be drawn, and the edge a valid wire becomes. React Flow handle ids are
 * `in:<port>` for inputs and `out:<port>` for outputs.
 */
import { portSpec } from '../../nodes/core/port-lookup.ts';
import { canConnect, type PortType } from '../../nodes/core/ports.ts';
import type { NodeRegistry } from '../../nodes/core/registry.ts';
import type { GraphDoc } from '../../nodes/graph/document.ts';
import { nodeDef } from '../../nodes/graph/group-def.ts';
import { closesCycle } from '../../nodes/graph/topo.ts';

export const inHandle = (port: string) => `in:${port}`;
export const outHandle = (port: string) => `out:${port}`;
export const portOfHandle = (handle: string | null | undefined) => handle?.replace(/^(in|out):/, '') ?? '';

export interface WireEnds {
  readonly source: string;
  readonly sourceHandle?: string | null;
  readonly target: string;
  readonly targetHandle?: string | null;
}

/** Port type of a node's output (`out`) or input (`in`), or null when unknown. */
export function portType(
  doc: GraphDoc,
  registry: NodeRegistry,
  nodeId: string,
  side: 'in' | 'out',
  port: string,
): PortType | null {
  const node = doc.nodes.find((n) => n.id === nodeId);
  const def = node && nodeDef(registry, node);
  if (!def) return null;
  return portSpec(def, side === 'in' ? 'inputs' : 'outputs', port)?.type ?? null;
}

export type ConnectionVerdict = { ok: true } | { ok: false; reason: string };

/** Why a wire may not be drawn: wrong types, a self loop, or a cycle. */
export function checkConnection(doc: GraphDoc, registry: NodeRegistry, wire: WireEnds): ConnectionVerdict {
  if (wire.source === wire.target) return { ok: false, reason: 'a node cannot feed itself' };
  const from = portType(doc, registry, wire.source, 'out', portOfHandle(wire.sourceHandle));
  const to = portType(doc, registry, wire.target, 'in', portOfHandle(wire.targetHandle));
  if (!from || !to) return { ok: false, reason: 'unknown port' };
  if (!canConnect(from, to)) return { ok: false, reason: `a ${from} output cannot feed a ${to} input` };
  const ids = doc.nodes.map((n) => n.id);
  const edges = doc.edges.map((e) => ({ from: e.from.node, to: e.to.node }));
  if (closesCycle(ids, edges, { from: wire.source, to: wire.target }))
    return { ok: false, reason: 'this wire would make a cycle' };
  return { ok: true };
}
