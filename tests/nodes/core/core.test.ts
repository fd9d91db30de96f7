import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import { defineNode } from '../../../nodes/core/define-node.ts';
import { diag, hasErrors } from '../../../nodes/core/diagnostics.ts';
import { hexColor, PORT_VALUE_SCHEMA, portValueToJson, toHex } from '../../../nodes/core/port-values.ts';
import { canConnect, isPortType, PORT_TYPE_INFO, PORT_TYPES } from '../../../nodes/core/ports.ts';
import { createRegistry } from '../../../nodes/core/registry.ts';
import { pointNode } from '../../../nodes/types/point.ts';

describe('colours in documents', () => {
  it('"#rrggbb" ↔ [r, g, b] round trips', () => {
    const hex = fc
      .array(fc.integer({ min: 0, max: 255 }), { minLength: 3, maxLength: 3 })
      .map((cs) => `#${cs.map((c) => c.toString(16).padStart(2, '0')).join('')}`);
    fc.assert(
      fc.property(hex, (s) => {
        const c = hexColor.parse(s);
        expect(toHex(c)).toBe(s);
        expect(portValueToJson('color', c)).toBe(s);
        expect(hexColor.parse(s.toUpperCase())).toEqual(c);
      }),
      { seed: 42, numRuns: 100 },
    );
    expect(toHex([2, -1, 0.5])).toBe('#ff0080'); // clamped
    expect(hexColor.safeParse('#fff').success).toBe(false);
  });

  it('other port values are stored as they are', () => {
    expect(portValueToJson('point', [1, 2])).toEqual([1, 2]);
    expect(PORT_VALUE_SCHEMA.element).toBeNull();
    expect(PORT_VALUE_SCHEMA.tile).toBeNull();
    expect(PORT_VALUE_SCHEMA.circle!.safeParse({ c: [0, 0], r: Number.NaN }).success).toBe(false);
  });
});

describe('port types', () => {
  it('connect only to themselves (and what they accept); element inputs take many edges', () => {
    for (const a of PORT_TYPES) {
      expect(canConnect(a, a)).toBe(true);
      for (const b of PORT_TYPES)
        if (a !== b) expect(canConnect(a, b)).toBe(PORT_TYPE_INFO[b].accepts.includes(a));
      expect(PORT_TYPE_INFO[a].color).toMatch(/^#[0-9a-f]{6}$/i);
    }
    expect(canConnect('point', 'circle')).toBe(false);
    expect(PORT_TYPE_INFO.element.many).toBe(true);
    expect(PORT_TYPE_INFO.point.many).toBe(false);
    expect(isPortType('circle')).toBe(true);
    expect(isPortType('banana')).toBe(false);
  });
});

describe('defineNode and the registry', () => {
  it('rejects ids that are not kebab-case', () => {
    for (const type of ['Point', 'my_node', 'two--dashes', '-lead', 'trail-', '3d']) {
      expect(() => defineNode({ ...pointNode, type })).toThrow(/kebab-case/);
    }
    expect(defineNode({ ...pointNode, type: 'circle-3pt' }).type).toBe('circle-3pt');
  });

  it('refuses a type registered twice', () => {
    expect(() => createRegistry([pointNode, pointNode])).toThrow(/twice/);
    const r = createRegistry([pointNode]);
    expect(r.get('point')).toBe(pointNode);
    expect(r.get('nope')).toBeUndefined();
  });
});

describe('diagnostics', () => {
  it('diag builds code, severity, message and location from the table', () => {
    const d = diag('cycle', { nodeId: 'a', path: 'nodes[0]' }, 'a → b → a');
    expect(d).toEqual({
      code: 'KF208',
      severity: 'error',
      message: 'cycle through nodes a → b → a',
      nodeId: 'a',
      path: 'nodes[0]',
    });
    expect(hasErrors([d])).toBe(true);
    expect(hasErrors([diag('noRender', {})])).toBe(false);
  });
});
