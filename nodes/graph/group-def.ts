/**
 * A group node's ports as a NodeDef (docs/architecture.md "Groups"), so the editor, the wiring
 * checks and the inspector treat a group like any node: each exposed input has the port type of
 * the first inner input it feeds, each exposed output the type of the inner output it reads.
 * Evaluation never calls it: groups are flattened first (flatten.ts).
 */
import type { InputSpecs, NodeDef, OutputSpecs } from '../core/define-node.ts';
import { inputSpec, outputSpec } from '../core/port-lookup.ts';
import type { NodeRegistry } from '../core/registry.ts';
import type { GraphNode } from './document.ts';

export const GROUP_TYPE = 'group';

const cache = new WeakMap<object, NodeDef>();

function innerDef(nodes: readonly GraphNode[], id: string, registry: NodeRegistry): NodeDef | undefined {
  const node = nodes.find((n) => n.id === id);
  return node ? nodeDef(registry, node) : undefined;
}

export function groupDef(node: GraphNode, registry: NodeRegistry): NodeDef | undefined {
  const body = node.group;
  if (!body) return undefined;
  const known = cache.get(body);
  if (known) return known;
  const inputs: Record<string, InputSpecs[string]> = {};
  for (const port of body.inputs) {
    const t = port.targets[0];
    const spec = inputSpec(innerDef(body.nodes, t.node, registry), t.port);
    // Wired-only: a group's input has no inline value of its own (its inner node keeps that).
    if (spec) inputs[port.name] = { type: spec.type, label: port.label ?? port.name, optional: true };
  }
  const outputs: Record<string, OutputSpecs[string]> = {};
  for (const port of body.outputs) {
    const spec = outputSpec(innerDef(body.nodes, port.from.node, registry), port.from.port);
    if (spec) outputs[port.name] = { type: spec.type, label: port.label ?? port.name };
  }
  const def: NodeDef = {
    type: GROUP_TYPE,
    version: 1,
    label: 'Group',
    category: 'Construction',
    color: '#8d99ae',
    doc: `A group of ${body.nodes.length} nodes: open it (double-click or Enter) to edit inside; Ctrl+Shift+G ungroups.`,
    inputs,
    outputs,
    params: {},
    evaluate: () => {
      throw new Error('groups are flattened before evaluation');
    },
  };
  cache.set(body, def);
  return def;
}

/** The NodeDef of any node: its type's, or its group's ports. */
export function nodeDef(registry: NodeRegistry, node: GraphNode): NodeDef | undefined {
  return node.group ? groupDef(node, registry) : registry.get(node.type);
}
