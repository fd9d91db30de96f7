/**
 * The one way to look up a name that comes from a document (a port, a param, a node type) in a
 * record: own properties only. A file may name a port "constructor", "toString" or "__proto__";
 * `record[name]` and `name in record` would then find Object.prototype's members (a function, an
 * object) where a spec was expected, and code such as `PORT_TYPE_INFO[spec.type].many` throws.
 */
import type { InputSpec, NodeDef, OutputSpec, ParamSpec } from './define-node.ts';

/**
 * `record[name]` when `name` is the record's own key (even when its value is undefined or null),
 * else `fallback` (undefined unless given; also when there is no record).
 */
export function ownEntry<T, F = undefined>(
  record: Readonly<Record<string, T>> | undefined,
  name: string,
  fallback?: F,
): T | F {
  return record !== undefined && Object.hasOwn(record, name) ? record[name] : (fallback as F);
}

/**
 * Stores `value` under `name` as an own key. Plain assignment would not for "__proto__" (it sets
 * the prototype instead), so a port or param of that name would silently vanish.
 */
export function setOwn<T>(record: Record<string, T>, name: string, value: T): void {
  // Plain assignment for every other name: this runs for every port of every node evaluated.
  if (name === '__proto__')
    Object.defineProperty(record, name, { value, writable: true, enumerable: true, configurable: true });
  else record[name] = value;
}

/** The spec of input `port` of a node type, or undefined when the type has no such input. */
export const inputSpec = (def: NodeDef | undefined, port: string): InputSpec | undefined =>
  ownEntry(def?.inputs, port);

/** The spec of output `port` of a node type, or undefined when the type has no such output. */
export const outputSpec = (def: NodeDef | undefined, port: string): OutputSpec | undefined =>
  ownEntry(def?.outputs, port);

/** The spec of non-wirable param `name` of a node type, or undefined when it has none. */
export const paramSpec = (def: NodeDef | undefined, name: string): ParamSpec | undefined =>
  ownEntry(def?.params, name);

/** The spec of a port on either side: `'inputs'` or `'outputs'`. */
export const portSpec = (
  def: NodeDef | undefined,
  side: 'inputs' | 'outputs',
  port: string,
): InputSpec | OutputSpec | undefined => (side === 'inputs' ? inputSpec(def, port) : outputSpec(def, port));
