/**
 * The rows of a node's body, in order: the params that switch other fields (so a select does
 * not jump while rows come and go below it), then the inputs, then the other params — only the
 * fields shown in the node's set-up (nodes/core/field-visibility.ts), split into the main list
 * and the collapsible "More" section. Pure: the node component and the layout estimate use it.
 */
import type { InputSpec, NodeDef, ParamSpec } from '../../nodes/core/define-node.ts';
import { controllingParams, isFieldInMore, isFieldShown } from '../../nodes/core/field-visibility.ts';

export type NodeField =
  | { readonly kind: 'input'; readonly name: string; readonly spec: InputSpec }
  | { readonly kind: 'param'; readonly name: string; readonly spec: ParamSpec };

export interface NodeFields {
  readonly main: readonly NodeField[];
  readonly more: readonly NodeField[];
}

/**
 * `forceShown` names fields shown whatever their condition (those with a diagnostic of their
 * own, so no problem hides), and kept out of "More".
 */
export function nodeFields(
  def: NodeDef,
  params: Readonly<Record<string, unknown>>,
  connected: ReadonlySet<string>,
  forceShown: ReadonlySet<string> = new Set(),
): NodeFields {
  const first = controllingParams(def);
  const ordered: NodeField[] = [
    ...first.map((name): NodeField => ({ kind: 'param', name, spec: def.params[name] })),
    ...Object.entries(def.inputs).map(([name, spec]): NodeField => ({ kind: 'input', name, spec })),
    ...Object.entries(def.params)
      .filter(([name]) => !first.includes(name))
      .map(([name, spec]): NodeField => ({ kind: 'param', name, spec })),
  ];
  const main: NodeField[] = [];
  const more: NodeField[] = [];
  for (const f of ordered) {
    const forced = forceShown.has(f.name);
    if (!forced && !isFieldShown(def, f.name, params, connected)) continue;
    (!forced && isFieldInMore(def, f.name, params, connected) ? more : main).push(f);
  }
  return { main, more };
}
