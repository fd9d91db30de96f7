/**
 * GraphDoc + evaluation → React Flow nodes and edges. Pure: the editor rebuilds these whenever
 * the document, evaluation or selection changes; React Flow never owns graph data.
 */
import type { Node } from '@xyflow/react';
import type { NodeDef } from '../../nodes/core/define-node.ts';
import type { Diagnostic } from '../../nodes/core/diagnostics.ts';
import { outputSpec } from '../../nodes/core/port-lookup.ts';
import { PORT_TYPE_INFO } from '../../nodes/core/ports.ts';
import type { NodeRegistry } from '../../nodes/core/registry.ts';
import type { GraphDoc, GraphNode } from '../../nodes/graph/document.ts';
import type { NodeEvaluation } from '../../nodes/graph/evaluate.ts';
import { nodeDef } from '../../nodes/graph/group-def.ts';
import { inHandle, outHandle } from './connection.ts';
import type { KfEdge } from './tools/RerouteEdge.tsx';

export interface KfNodeData extends Record<string, unknown> {
  readonly node: GraphNode;
  readonly def: NodeDef | undefined;
  /** Inputs that have an edge (they show no inline widget). */
  readonly connected: ReadonlySet<string>;
  /** For the read-out: kept from an earlier evaluation while read-out and diagnostics are unchanged. */
  readonly evaluation: NodeEvaluation | undefined;
  readonly diagnostics: readonly Diagnostic[];
  /** Ports named by edges of an unknown-type node (so its wires still show). */
  readonly orphanPorts: { readonly inputs: readonly string[]; readonly outputs: readonly string[] };
  readonly hovered: boolean;
}

export type KfNode = Node<KfNodeData, 'kf'>;

export function diagnosticsByNode(diagnostics: readonly Diagnostic[]): Map<string, Diagnostic[]> {
  const by = new Map<string, Diagnostic[]>();
  for (const d of diagnostics) {
    if (!d.nodeId) continue;
    const list = by.get(d.nodeId) ?? [];
    if (!list.some((x) => x.code === d.code && x.message === d.message)) list.push(d);
    by.set(d.nodeId, list);
  }
  return by;
}

const sameList = (a: readonly string[], b: readonly string[]) =>
  a.length === b.length && a.every((x, i) => x === b[i]);
const sameDiagnostics = (a: readonly Diagnostic[], b: readonly Diagnostic[]) =>
  a.length === b.length &&
  a.every(
    (d, i) =>
      d.code === b[i].code &&
      d.message === b[i].message &&
      d.severity === b[i].severity &&
      d.port === b[i].port,
  );

/**
 * `prev` when nothing the node shows changed (same document node, wires, read-out, diagnostics,
 * hover): its React Flow node keeps its identity and does not re-render. With hundreds of nodes a
 * rebuild of every node per selection, hover or drop costs a visible hitch.
 */
function reuseData(prev: KfNodeData | undefined, next: KfNodeData): KfNodeData {
  const same =
    prev !== undefined &&
    prev.node === next.node &&
    prev.def === next.def &&
    prev.hovered === next.hovered &&
    prev.evaluation?.readout === next.evaluation?.readout &&
    sameList([...prev.connected], [...next.connected]) &&
    sameDiagnostics(prev.diagnostics, next.diagnostics) &&
    sameList(prev.orphanPorts.inputs, next.orphanPorts.inputs) &&
    sameList(prev.orphanPorts.outputs, next.orphanPorts.outputs);
  return same ? prev : next;
}

/** What a screen reader says on reaching a node: its name, its type, and how many problems. */
function nodeAriaLabel({ node, def, diagnostics }: KfNodeData): string {
  const type = def?.label ?? node.type;
  const name = node.label ? `${node.label}, ${type}` : type;
  const problems = diagnostics.filter((d) => d.severity !== 'info').length;
  return `${name} node${node.muted ? ', muted' : ''}${problems ? `, ${problems} problem${problems === 1 ? '' : 's'}` : ''}`;
}

export function toFlowNodes(
  doc: GraphDoc,
  registry: NodeRegistry,
  evaluations: ReadonlyMap<string, NodeEvaluation>,
  diagnostics: ReadonlyMap<string, readonly Diagnostic[]>,
  selection: ReadonlySet<string>,
  hovered: string | null,
  previous: ReadonlyMap<string, KfNode>,
): KfNode[] {
  const connected = new Map<string, Set<string>>();
  for (const e of doc.edges) {
    const set = connected.get(e.to.node) ?? new Set<string>();
    set.add(e.to.port);
    connected.set(e.to.node, set);
  }
  return doc.nodes.map((node) => {
    const def = nodeDef(registry, node);
    const prev = previous.get(node.id);
    const orphanPorts = def
      ? { inputs: [], outputs: [] }
      : {
          inputs: [...new Set(doc.edges.filter((e) => e.to.node === node.id).map((e) => e.to.port))],
          outputs: [...new Set(doc.edges.filter((e) => e.from.node === node.id).map((e) => e.from.port))],
        };
    const data = reuseData(prev?.data, {
      node,
      def,
      connected: connected.get(node.id) ?? new Set(),
      evaluation: evaluations.get(node.id),
      diagnostics: diagnostics.get(node.id) ?? [],
      orphanPorts,
      hovered: hovered === node.id,
    });
    const [x, y] = node.position;
    const selected = selection.has(node.id);
    if (prev?.data === data && prev.selected === selected && prev.position.x === x && prev.position.y === y)
      return prev;
    return {
      id: node.id,
      type: 'kf',
      position: { x, y },
      selected,
      ...(prev?.measured ? { measured: prev.measured } : {}),
      ariaLabel: nodeAriaLabel(data),
      data,
    };
  });
}

export function toFlowEdges(
  doc: GraphDoc,
  registry: NodeRegistry,
  selectedEdges: ReadonlySet<string>,
): KfEdge[] {
  const types = new Map(doc.nodes.map((n) => [n.id, nodeDef(registry, n)]));
  return doc.edges.map((e) => {
    const type = outputSpec(types.get(e.from.node), e.from.port)?.type;
    const color = type ? PORT_TYPE_INFO[type].color : '#888';
    return {
      id: e.id,
      type: 'kf',
      data: { via: e.via ?? [] },
      source: e.from.node,
      sourceHandle: outHandle(e.from.port),
      target: e.to.node,
      targetHandle: inHandle(e.to.port),
      selected: selectedEdges.has(e.id),
      style: { stroke: color },
      className: `kf-edge kf-edge--${type ?? 'unknown'}`,
    };
  });
}
