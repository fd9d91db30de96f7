/**
 * Names every JavaScript object has ("constructor", "toString", "__proto__") as ports and params:
 * the one lookup (nodes/core/port-lookup.ts) finds only a type's own ports, so a document that
 * names them gets "unknown port", and a type that declares them works like any other.
 */
import { describe, expect, it } from 'vitest';
import { defineNode, type InputSpec, type OutputSpec } from '../../../nodes/core/define-node.ts';
import { isFieldShown } from '../../../nodes/core/field-visibility.ts';
import { inputSpec, outputSpec, ownEntry, paramSpec } from '../../../nodes/core/port-lookup.ts';
import { createRegistry } from '../../../nodes/core/registry.ts';
import { evaluateGraph } from '../../../nodes/graph/evaluate.ts';
import { resolveParams } from '../../../nodes/graph/params.ts';
import { registry as appRegistry } from '../../../nodes/types/index.ts';
import { checkConnection, inHandle, outHandle, portType } from '../../../src/editor/connection.ts';
import { applyChange, inputTakesMany } from '../../../src/state/changes.ts';
import { doc, edge, node } from '../support/doc.ts';

const NAMES = ['constructor', 'toString', '__proto__'] as const;

/** A record with `name` as an own key; JSON.parse makes even "__proto__" an ordinary key. */
const withOwn = <T>(name: string, value: T): Record<string, T> =>
  JSON.parse(JSON.stringify({ [`${name}`]: value, other: value }));

const numberIn: InputSpec = { type: 'number', label: 'n', default: 3 };
const numberOut: OutputSpec = { type: 'number' };

/** A type whose ports are named after Object.prototype's members: out[name] = in[name] + 1. */
const oddType = (name: string) =>
  defineNode({
    type: 'test-odd',
    version: 1,
    label: 'Odd',
    category: 'Values',
    color: '#000000',
    doc: 'ports with awkward names',
    inputs: withOwn(name, numberIn),
    outputs: withOwn(name, numberOut),
    params: {},
    evaluate: ({ inputs }) => ({
      outputs: withOwn(name, (ownEntry(inputs as Record<string, unknown>, name) as number) + 1),
    }),
  });

describe('ownEntry and the spec lookups', () => {
  for (const name of NAMES) {
    it(`"${name}" is found only as an own key`, () => {
      expect(ownEntry({}, name)).toBeUndefined();
      expect(ownEntry({}, name, 'fallback')).toBe('fallback');
      expect(ownEntry(withOwn(name, 7), name)).toBe(7);
      const circle = appRegistry.get('circle');
      expect(inputSpec(circle, name)).toBeUndefined();
      expect(outputSpec(circle, name)).toBeUndefined();
      expect(paramSpec(circle, name)).toBeUndefined();
      expect(inputSpec(oddType(name), name)).toEqual(numberIn);
    });
  }

  it('an own key whose value is undefined or null is found, not replaced by the fallback', () => {
    expect(ownEntry({ a: null }, 'a', 1)).toBeNull();
    expect(ownEntry({ a: undefined }, 'a', 1)).toBeUndefined();
    expect(ownEntry(undefined, 'a', 1)).toBe(1);
  });
});

describe('a document that names Object.prototype members as ports', () => {
  const d = doc([node('c', 'circle'), node('i', 'inversion'), node('out', 'render')]);
  for (const name of NAMES) {
    it(`"${name}": the editor refuses the wire, changes keep the document, nothing throws`, () => {
      expect(portType(d, appRegistry, 'out', 'in', name)).toBeNull();
      expect(portType(d, appRegistry, 'c', 'out', name)).toBeNull();
      const wire = {
        source: 'i',
        sourceHandle: outHandle('element'),
        target: 'out',
        targetHandle: inHandle(name),
      };
      expect(checkConnection(d, appRegistry, wire)).toEqual({ ok: false, reason: 'unknown port' });
      expect(inputTakesMany(d, appRegistry, { node: 'out', port: name })).toBe(false);
      const connect = (from: string, to: string) =>
        applyChange(d, { type: 'connect', edge: edge('e9', from, to) }, appRegistry);
      expect(connect('i.element', `out.${name}`)).toBe(d);
      expect(connect(`c.${name}`, 'i.circle')).toBe(d);
      expect(isFieldShown(appRegistry.get('circle')!, name, {})).toBe(false);
    });
  }
});

describe('a node type that declares them', () => {
  for (const name of NAMES) {
    it(`"${name}" works as an input, an output and a stored value`, () => {
      const odd = oddType(name);
      const registry = createRegistry([...appRegistry.all, odd]);
      const params = withOwn(name, 10);
      const two = doc(
        [{ ...node('a', 'test-odd'), params }, node('b', 'test-odd')],
        [edge('e1', `a.${name}`, `b.${name}`)],
      );
      const ev = evaluateGraph(two, registry);
      expect(ev.diagnostics.filter((x) => x.nodeId === 'a' || x.nodeId === 'b')).toEqual([]);
      expect(ownEntry(ev.nodes.get('a')?.outputs, name)).toBe(11); // the stored 10, plus one
      expect(ownEntry(ev.nodes.get('b')?.outputs, name)).toBe(12); // the wire carries a's output
      const resolved = resolveParams(odd, { id: 'a', params: {} }, new Map(), ['nodes', 0]);
      expect(ownEntry(resolved.inline, name)).toBe(3); // the default
      expect(
        checkConnection(two, registry, {
          source: 'a',
          sourceHandle: outHandle(name),
          target: 'b',
          targetHandle: inHandle(name),
        }),
      ).toEqual({ ok: true });
    });
  }
});
