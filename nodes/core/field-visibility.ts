/**
 * Which of a node's fields (inputs and params) the editor shows, from the `when` / `more` each
 * declares: a field that means nothing in the chosen set-up (the palette colours while colouring
 * by picture) is hidden; its value stays in the document. Pure, so the node component, the
 * inspector and the layout estimate all agree.
 */
import type { FieldCondition, NodeDef, ParamSpec } from './define-node.ts';
import { inputSpec, ownEntry, paramSpec } from './port-lookup.ts';

const NONE: ReadonlySet<string> = new Set();

/** A field's declaration, input or param. */
const fieldSpec = (def: NodeDef, name: string) => inputSpec(def, name) ?? paramSpec(def, name);

/** The value a controlling param has: the stored one when valid for its spec, else its default. */
export function controlValue(spec: ParamSpec, stored: unknown): unknown {
  if (spec.kind === 'enum')
    return typeof stored === 'string' && spec.options.includes(stored) ? stored : spec.default;
  if (spec.kind === 'boolean') return typeof stored === 'boolean' ? stored : spec.default;
  return stored ?? spec.default;
}

/**
 * Whether `cond` holds: its param has one of the listed values AND that param is itself shown
 * (a toggle hidden in this mode cannot switch anything on). `depth` cuts a cycle of conditions,
 * which the contract test forbids anyway; an unknown param counts as holding, so a mistake in a
 * declaration shows too much rather than losing a field.
 */
function holds(
  def: NodeDef,
  cond: FieldCondition | undefined,
  params: Readonly<Record<string, unknown>>,
  depth: number,
): boolean {
  if (!cond) return true;
  const control = paramSpec(def, cond.param);
  if (!control || depth > Object.keys(def.params).length) return true;
  const value = controlValue(control, ownEntry(params, cond.param));
  return cond.is.includes(value as string | boolean) && holds(def, control.when, params, depth + 1);
}

/**
 * Whether the editor shows field `name` (an input or param of `def`) for a node with document
 * params `params`: a wired input always (no wire may disappear), else while its `when` holds.
 */
export function isFieldShown(
  def: NodeDef,
  name: string,
  params: Readonly<Record<string, unknown>>,
  connected: ReadonlySet<string> = NONE,
): boolean {
  if (connected.has(name) && inputSpec(def, name)) return true;
  const spec = fieldSpec(def, name);
  return spec ? holds(def, spec.when, params, 0) : false;
}

/**
 * Whether a shown field belongs in the node's collapsible "More" section: declared `more`
 * (always, or while its condition holds), and not wired (a wire's port stays in sight).
 */
export function isFieldInMore(
  def: NodeDef,
  name: string,
  params: Readonly<Record<string, unknown>>,
  connected: ReadonlySet<string> = NONE,
): boolean {
  const more = fieldSpec(def, name)?.more;
  if (!more || connected.has(name)) return false;
  return more === true || holds(def, more, params, 0);
}

/** The params other fields depend on (the editor puts these switches first, so they do not jump). */
export function controllingParams(def: NodeDef): readonly string[] {
  const named = new Set<string>();
  for (const spec of [...Object.values(def.inputs), ...Object.values(def.params)]) {
    if (spec.when) named.add(spec.when.param);
    if (spec.more && spec.more !== true) named.add(spec.more.param);
  }
  return Object.keys(def.params).filter((p) => named.has(p));
}
