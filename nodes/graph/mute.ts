/**
 * What a muted (bypassed) node passes on (docs/architecture.md "Muted nodes"): each `element`
 * (or space `element3`) output is the empty list (a muted mirror or generator contributes no elements, so the picture is
 * the graph without it); any other output passes the value of the node's first input of the same
 * port type through (in declaration order); an output with neither is absent, and its dependants
 * report "input muted" (KF313) instead of an error.
 */
import type { NodeDef } from '../core/define-node.ts';
import { ownEntry } from '../core/port-lookup.ts';
import { PORT_TYPE_INFO } from '../core/ports.ts';

export function mutedOutputs(
  def: NodeDef,
  inputs: Readonly<Record<string, unknown>>,
): Readonly<Record<string, unknown>> {
  const out: Record<string, unknown> = {};
  for (const [port, spec] of Object.entries(def.outputs)) {
    // Element lists, plane and space alike: a muted mirror contributes none.
    if (spec.type === 'element' || spec.type === 'element3') {
      out[port] = [];
      continue;
    }
    // A many-input's value is a list while the output is one value: those never pass through.
    if (PORT_TYPE_INFO[spec.type].many) continue;
    const same = Object.entries(def.inputs).find(([, s]) => s.type === spec.type);
    const value = same ? ownEntry(inputs, same[0]) : undefined;
    if (value !== undefined) out[port] = value;
  }
  return out;
}
