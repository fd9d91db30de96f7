/**
 * The contract every registered node type keeps. Loops over `registry.all`, so node types added
 * later are checked without touching this file.
 */
import { describe, expect, it } from 'vitest';
import type { NodeDef } from '../../../nodes/core/define-node.ts';
import { PORT_VALUE_SCHEMA } from '../../../nodes/core/port-values.ts';
import { isPortType } from '../../../nodes/core/ports.ts';
import type { Vec2 } from '../../../nodes/core/values.ts';
import { allFinite, evaluateGraph } from '../../../nodes/graph/evaluate.ts';
import { loadDocument } from '../../../nodes/graph/load.ts';
import { resolveParams } from '../../../nodes/graph/params.ts';
import { registry } from '../../../nodes/types/index.ts';
import { doc, node } from '../support/doc.ts';

const CATEGORIES = [
  'Values',
  'Geometry',
  'Construction',
  'Generators',
  'Kaleidoscopes',
  'Colour',
  'Animation',
  'Output',
  '3D',
];
const nonEmpty = (s: unknown) => typeof s === 'string' && s.trim().length > 0;
const finitePoint = (p: unknown) =>
  Array.isArray(p) && p.length === 2 && p.every((v) => typeof v === 'number' && Number.isFinite(v));

/** Evaluates a document holding only a node of this type with `params`. */
const alone = (def: NodeDef, params: Record<string, unknown> = {}) =>
  evaluateGraph(doc([node('n', def.type, params)]), registry);

describe('the registry', () => {
  it('holds node types with unique ids', () => {
    expect(registry.all.length).toBeGreaterThanOrEqual(12);
    const ids = registry.all.map((d) => d.type);
    expect(new Set(ids).size).toBe(ids.length);
    for (const id of ids) expect(registry.get(id)?.type).toBe(id);
  });
});

describe.each(registry.all.map((def) => [def.type, def] as const))('node type "%s"', (_type, def) => {
  it('has a kebab-case id, a version and its UI metadata', () => {
    expect(def.type).toMatch(/^[a-z][a-z0-9]*(-[a-z0-9]+)*$/);
    expect(Number.isInteger(def.version) && def.version >= 1).toBe(true);
    expect(nonEmpty(def.label)).toBe(true);
    expect(CATEGORIES).toContain(def.category);
    expect(def.color).toMatch(/^#[0-9a-fA-F]{6}$/);
    expect(nonEmpty(def.doc)).toBe(true);
  });

  it('labels every input; inline-editable inputs have a default that validates', () => {
    for (const [name, spec] of Object.entries(def.inputs)) {
      expect(isPortType(spec.type), `${name}: port type`).toBe(true);
      expect(nonEmpty(spec.label), `input "${name}" has a label`).toBe(true);
      if (PORT_VALUE_SCHEMA[spec.type] && !spec.optional) {
        expect(spec.default, `input "${name}" has a default`).toBeDefined();
      }
    }
    const r = resolveParams(def, { id: 'n', params: {} }, new Set(), ['nodes', 0]);
    expect(r.diagnostics).toEqual([]);
    for (const [name, spec] of Object.entries(def.inputs)) {
      if (PORT_VALUE_SCHEMA[spec.type] && spec.default !== undefined) expect(name in r.inline).toBe(true);
    }
    for (const name of Object.keys(def.params)) expect(name in r.params).toBe(true);
  });

  it('declares its outputs (only an Output node may have none)', () => {
    for (const [name, spec] of Object.entries(def.outputs)) expect(isPortType(spec.type), name).toBe(true);
    if (def.category !== 'Output') expect(Object.keys(def.outputs).length).toBeGreaterThan(0);
    const clash = Object.keys(def.inputs).filter((k) => Object.hasOwn(def.params, k));
    expect(clash, 'an input and a param share a name').toEqual([]);
  });

  it('names an existing enum or toggle, with legal values and no cycle, in every when / more', () => {
    const fields = [...Object.entries(def.inputs), ...Object.entries(def.params)];
    for (const [name, spec] of fields) {
      for (const cond of [spec.when, spec.more === true ? undefined : spec.more]) {
        if (!cond) continue;
        const control = Object.hasOwn(def.params, cond.param) ? def.params[cond.param] : undefined;
        expect(control?.kind, `${name}: "${cond.param}" is an enum or boolean param`).toMatch(
          /^(enum|boolean)$/,
        );
        expect(cond.param, `${name} depends on itself`).not.toBe(name);
        expect(cond.is.length, `${name}: lists at least one value`).toBeGreaterThan(0);
        const legal: readonly unknown[] = control?.kind === 'enum' ? control.options : [true, false];
        for (const v of cond.is) expect(legal, `${name}: value ${String(v)} of "${cond.param}"`).toContain(v);
      }
      // following `when` from param to param ends (isFieldShown would cut a cycle, hiding a bug)
      const seen = new Set([name]);
      for (let c = spec.when; c; c = def.params[c.param]?.when) {
        expect(seen.has(c.param), `${name}: a cycle of conditions through "${c.param}"`).toBe(false);
        seen.add(c.param);
      }
    }
  });

  it('has a migration for every version below its own', () => {
    for (let v = 1; v < def.version; v++)
      expect(typeof def.migrations?.[v], `migration ${v} → ${v + 1}`).toBe('function');
    // and a node written for any older version (no version = 1) loads (migrated once, on load)
    // and then evaluates with its defaults
    for (let v = 1; v <= def.version; v++) {
      const loaded = loadDocument(doc([{ ...node('n', def.type), version: v }]), registry);
      if (!loaded.ok) throw new Error(`from version ${v}: ${JSON.stringify(loaded.diagnostics)}`);
      const ev = evaluateGraph(loaded.doc, registry);
      expect(
        ev.diagnostics.filter((d) => d.severity === 'error'),
        `from version ${v}`,
      ).toEqual([]);
    }
  });

  it('evaluates alone, with its defaults, without errors and deterministically', () => {
    const ev = alone(def);
    const own = ev.nodes.get('n')!;
    expect(own.diagnostics.filter((d) => d.severity === 'error')).toEqual([]);
    expect(own.outputs).toBeDefined();
    expect(allFinite(own.outputs)).toBe(true);
    for (const port of Object.keys(own.outputs!)) expect(Object.hasOwn(def.outputs, port), port).toBe(true);
    expect(alone(def).nodes.get('n')!.outputs).toEqual(own.outputs);
  });

  it('overlay, handles and drag give finite positions and touch only its own inputs/params', () => {
    const own = alone(def).nodes.get('n')!;
    const ctx = own.ctx!;
    const outputs = own.outputs!;
    for (const shape of def.overlay?.(ctx, outputs) ?? []) {
      if (shape.shape === 'point') expect(finitePoint(shape.at)).toBe(true);
      if (shape.shape === 'line') expect(finitePoint(shape.line.a) && finitePoint(shape.line.b)).toBe(true);
      if (shape.shape === 'circle') {
        expect(finitePoint(shape.circle.c)).toBe(true);
        expect(shape.circle.r).toBeGreaterThan(0);
      }
    }
    const handles = def.handles?.(ctx, outputs) ?? [];
    expect(new Set(handles.map((h) => h.handle)).size).toBe(handles.length);
    for (const h of handles) expect(finitePoint(h.at), h.handle).toBe(true);
    if (handles.length > 0) expect(def.drag, 'handles without drag').toBeDefined();
    for (const h of handles) {
      const to: Vec2 = [h.at[0] + 0.1, h.at[1] + 0.05];
      const change = def.drag!(h.handle, to, ctx);
      const keys = Object.keys(change);
      expect(keys.length, `drag of "${h.handle}" changes something`).toBeGreaterThan(0);
      for (const k of keys)
        expect(Object.hasOwn(def.inputs, k) || Object.hasOwn(def.params, k), k).toBe(true);
      // the dragged values are valid document params and the node still evaluates
      const moved = alone(def, { ...change }).nodes.get('n')!;
      expect(
        moved.diagnostics.filter((d) => d.severity === 'error'),
        `after dragging "${h.handle}"`,
      ).toEqual([]);
      const again = def.handles!(moved.ctx!, moved.outputs!).find((x) => x.handle === h.handle);
      expect(again && finitePoint(again.at)).toBe(true);
    }
  });
});
