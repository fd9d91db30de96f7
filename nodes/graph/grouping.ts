/**
 * Group and ungroup (docs/architecture.md "Groups"), pure on documents. Grouping moves the chosen
 * nodes and the wires between them into one group node, exposing one input per outside output
 * that feeds the selection (wired inside to every port it fed) and one output per inner output
 * read outside; a frame whose nodes are all chosen goes inside with them. Ungrouping puts
 * everything back: nodes, params, positions, ids and frames as they were.
 */
import type { GraphDoc, GraphEdge, GraphFrame, GraphNode, PortRef } from './document.ts';
import { nodesInFrame } from './frames.ts';
import { GROUP_TYPE } from './group-def.ts';

type Graph = Pick<GraphDoc, 'nodes' | 'edges' | 'frames'>;

/** `graph` with these frames; none removes the key (a graph without frames stays as it was). */
function withFrames<G extends Graph>(graph: G, frames: readonly GraphFrame[]): G {
  const { frames: _old, ...rest } = graph;
  return (frames.length > 0 ? { ...rest, frames } : rest) as G;
}
const key = (r: PortRef) => JSON.stringify([r.node, r.port]);

/** `wanted`, or `wanted2`, `wanted3`… — the first not in `taken` (which it joins). */
function uniqueName(wanted: string, taken: Set<string>): string {
  let name = wanted;
  for (let i = 2; taken.has(name); i++) name = `${wanted}${i}`;
  taken.add(name);
  return name;
}

/**
 * The graph with the nodes `ids` replaced by the group node `groupId` (placed at their top-left
 * corner, where the first of them was in the list). Unknown ids are ignored; none known → `graph`.
 */
export function groupNodes<G extends Graph>(graph: G, ids: Iterable<string>, groupId: string): G {
  const inside = new Set(ids);
  const chosen = graph.nodes.filter((n) => inside.has(n.id));
  if (chosen.length === 0) return graph;
  const byId = new Map(chosen.map((n) => [n.id, n]));
  const isIn = (r: PortRef) => byId.has(r.node);
  const names = new Set<string>();
  const inputs = new Map<string, { name: string; label: string; targets: PortRef[]; edge: GraphEdge }>();
  const outputs = new Map<string, { name: string; label: string; from: PortRef }>();
  const edges: GraphEdge[] = [];
  const innerEdges: GraphEdge[] = [];
  const nameOf = (r: PortRef) => `${byId.get(r.node)?.label ?? r.node} ${r.port}`;
  for (const e of graph.edges) {
    if (isIn(e.from) && isIn(e.to)) innerEdges.push(e);
    else if (isIn(e.to)) {
      const k = key(e.from);
      const known = inputs.get(k);
      if (known) {
        known.targets.push(e.to);
        continue;
      }
      const name = uniqueName(e.to.port, names);
      inputs.set(k, { name, label: nameOf(e.to), targets: [e.to], edge: e });
      edges.push({ ...e, to: { node: groupId, port: name } });
    } else if (isIn(e.from)) {
      const k = key(e.from);
      let out = outputs.get(k);
      if (!out) {
        out = { name: uniqueName(e.from.port, names), label: nameOf(e.from), from: e.from };
        outputs.set(k, out);
      }
      edges.push({ ...e, from: { node: groupId, port: out.name } });
    } else edges.push(e);
  }
  // A frame goes inside when it carries nodes and all of them are grouped.
  const carried = new Set(
    (graph.frames ?? []).filter((f) => {
      const ids = nodesInFrame(graph.nodes, f);
      return ids.length > 0 && ids.every((id) => inside.has(id));
    }),
  );
  const group: GraphNode = {
    id: groupId,
    type: GROUP_TYPE,
    position: [Math.min(...chosen.map((n) => n.position[0])), Math.min(...chosen.map((n) => n.position[1]))],
    params: {},
    group: {
      nodes: chosen,
      edges: innerEdges,
      inputs: [...inputs.values()].map(({ name, label, targets }) => ({ name, label, targets })),
      outputs: [...outputs.values()],
      ...(carried.size > 0 ? { frames: [...carried] } : {}),
    },
  };
  const first = graph.nodes.findIndex((n) => inside.has(n.id));
  const nodes = graph.nodes.flatMap((n, i) => (i === first ? [group] : inside.has(n.id) ? [] : [n]));
  const grouped = { ...graph, nodes, edges };
  return carried.size > 0
    ? withFrames(
        grouped,
        (graph.frames ?? []).filter((f) => !carried.has(f)),
      )
    : grouped;
}

/**
 * The graph with group `groupId` replaced by its nodes and wires. Inner ids that another node or
 * edge now has are renamed with `freshId`; the nodes move by however far the group node was moved
 * since grouping (so a group dragged elsewhere ungroups where it is).
 */
export function ungroupNode<G extends Graph>(
  graph: G,
  groupId: string,
  freshId: (prefix: string) => string,
): G {
  const at = graph.nodes.findIndex((n) => n.id === groupId);
  const group = graph.nodes[at];
  const body = group?.group;
  if (!body) return graph;
  const taken = new Set([
    ...graph.nodes.filter((n) => n.id !== groupId).map((n) => n.id),
    ...graph.edges.map((e) => e.id),
    ...(graph.frames ?? []).map((f) => f.id),
  ]);
  const rename = (id: string) => (taken.has(id) ? freshId(id.replace(/\d+$/, '')) : id);
  const ids = new Map(body.nodes.map((n) => [n.id, rename(n.id)]));
  for (const id of ids.values()) taken.add(id);
  const [dx, dy] = [
    group.position[0] - Math.min(...body.nodes.map((n) => n.position[0])),
    group.position[1] - Math.min(...body.nodes.map((n) => n.position[1])),
  ];
  const inner = body.nodes.map((n) => ({
    ...n,
    id: ids.get(n.id)!,
    position: [n.position[0] + dx, n.position[1] + dy] as [number, number],
  }));
  const ref = (r: PortRef): PortRef | null => {
    const id = ids.get(r.node);
    return id === undefined ? null : { node: id, port: r.port };
  };
  const edges: GraphEdge[] = [];
  for (const e of graph.edges) {
    if (e.to.node === groupId) {
      const targets = body.inputs.find((p) => p.name === e.to.port)?.targets ?? [];
      targets.forEach((t, k) => {
        const to = ref(t);
        if (to) edges.push({ ...e, id: k === 0 ? e.id : freshId('e'), to });
      });
    } else if (e.from.node === groupId) {
      const port = body.outputs.find((p) => p.name === e.from.port);
      const from = port && ref(port.from);
      if (from) edges.push({ ...e, from });
    } else edges.push(e);
  }
  for (const e of body.edges) {
    const from = ref(e.from);
    const to = ref(e.to);
    if (from && to) edges.push({ ...e, id: taken.has(e.id) ? freshId('e') : e.id, from, to });
  }
  const nodes = [...graph.nodes.slice(0, at), ...inner, ...graph.nodes.slice(at + 1)];
  const ungrouped = { ...graph, nodes, edges };
  if (!body.frames?.length) return ungrouped;
  const frames = body.frames.map((f) => ({
    ...f,
    id: taken.has(f.id) ? freshId(f.id.replace(/\d+$/, '')) : f.id,
    position: [f.position[0] + dx, f.position[1] + dy] as [number, number],
  }));
  return withFrames(ungrouped, [...(graph.frames ?? []), ...frames]);
}
