/**
 * Checks a node's `params` against its type: inline values of unconnected inputs (by port type)
 * and non-wirable params (by ParamSpec). Missing entries take defaults; every problem names its path.
 */
import type { InputSpec, NodeDef, ParamSpec } from '../core/define-node.ts';
import { type Diagnostic, diag } from '../core/diagnostics.ts';
import { inputSpec, ownEntry, paramSpec, setOwn } from '../core/port-lookup.ts';
import { hexColor, PORT_VALUE_SCHEMA } from '../core/port-values.ts';
import { describeValue } from './describe-value.ts';
import { formatPath } from './json-path.ts';

export interface ResolvedParams {
  /** Runtime values of unconnected inputs that have an inline value. */
  readonly inline: Record<string, unknown>;
  /** Non-wirable params with defaults filled in (colours as [r, g, b]). */
  readonly params: Record<string, unknown>;
  readonly diagnostics: Diagnostic[];
}

/** Range/integer check shared by inline values, wired values and number params. */
export function checkNumber(
  spec: { min?: number; max?: number; integer?: boolean },
  v: number,
): string | null {
  if (!Number.isFinite(v)) return `expected a finite number, got ${v}`;
  if (spec.integer && !Number.isInteger(v)) return `expected an integer, got ${v}`;
  if (spec.min !== undefined && v < spec.min) return `expected a number ≥ ${spec.min}, got ${v}`;
  if (spec.max !== undefined && v > spec.max) return `expected a number ≤ ${spec.max}, got ${v}`;
  return null;
}

const describe = (v: unknown) => describeValue(v);

function parseInput(spec: InputSpec, raw: unknown): { value?: unknown; problem?: string } {
  // Numbers are most inline values: checkNumber is the whole check, no schema run needed (speed).
  if (spec.type === 'number' && Number.isFinite(raw)) {
    const problem = checkNumber(spec, raw as number);
    return problem ? { problem } : { value: raw };
  }
  const schema = PORT_VALUE_SCHEMA[spec.type];
  if (!schema) return {};
  const parsed = schema.safeParse(raw);
  if (!parsed.success) return { problem: `expected a ${spec.type} value, got ${describe(raw)}` };
  if (spec.type === 'number') {
    const problem = checkNumber(spec, parsed.data as number);
    if (problem) return { problem };
  }
  return { value: parsed.data };
}

function parseParam(spec: ParamSpec, raw: unknown): { value?: unknown; problem?: string } {
  switch (spec.kind) {
    case 'boolean':
      return typeof raw === 'boolean'
        ? { value: raw }
        : { problem: `expected true or false, got ${describe(raw)}` };
    case 'enum':
      return typeof raw === 'string' && spec.options.includes(raw)
        ? { value: raw }
        : {
            problem: `expected one of ${spec.options.map((o) => `"${o}"`).join(', ')}, got ${describe(raw)}`,
          };
    case 'number': {
      if (typeof raw !== 'number') return { problem: `expected a number, got ${describe(raw)}` };
      const problem = checkNumber(spec, raw);
      return problem ? { problem } : { value: raw };
    }
    case 'color': {
      const parsed = hexColor.safeParse(raw);
      return parsed.success
        ? { value: parsed.data }
        : { problem: `expected a colour like "#ff8800", got ${describe(raw)}` };
    }
    case 'string': {
      const max = spec.maxLength ?? 10_000;
      return typeof raw === 'string' && raw.length <= max
        ? { value: raw }
        : { problem: `expected text (at most ${max} characters), got ${describe(raw)}` };
    }
  }
}

/**
 * @param connected names of inputs that have an edge (their inline value is ignored but kept).
 * @param path the node's path in the document, e.g. ['nodes', 3].
 */
export function resolveParams(
  def: NodeDef,
  node: { id: string; params: Record<string, unknown> },
  connected: { has(name: string): boolean },
  path: readonly PropertyKey[],
): ResolvedParams {
  const inline: Record<string, unknown> = {};
  const params: Record<string, unknown> = {};
  const diagnostics: Diagnostic[] = [];
  const problem = (name: string, text: string) =>
    diagnostics.push(
      diag(
        'badParam',
        { nodeId: node.id, port: name, path: formatPath([...path, 'params', name]) },
        name,
        text,
      ),
    );

  for (const [name, spec] of Object.entries(def.inputs)) {
    if (connected.has(name) || !PORT_VALUE_SCHEMA[spec.type]) continue;
    const raw = ownEntry(node.params, name, spec.default);
    if (raw === undefined) continue; // optional input with no value: the node decides
    const r = parseInput(spec, raw);
    if (r.problem) problem(name, r.problem);
    else setOwn(inline, name, r.value);
  }
  for (const [name, spec] of Object.entries(def.params)) {
    const raw = ownEntry(node.params, name, spec.default);
    const r = parseParam(spec, raw);
    if (r.problem) problem(name, r.problem);
    else setOwn(params, name, r.value);
  }
  for (const name of Object.keys(node.params)) {
    if (!inputSpec(def, name) && !paramSpec(def, name)) {
      diagnostics.push({
        ...diag(
          'badParam',
          { nodeId: node.id, path: formatPath([...path, 'params', name]) },
          name,
          `"${def.type}" has no parameter "${name}" (kept, ignored)`,
        ),
        severity: 'warning',
      });
    }
  }
  return { inline, params, diagnostics };
}
