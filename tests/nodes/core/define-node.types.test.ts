/**
 * defineNode types a node from its own declarations. The `@ts-expect-error` lines are checked by
 * `tsc` (part of `npm test`): each must be an error, or the type check fails. The runtime part
 * evaluates the same definition through a registry, where it is stored erased.
 */
import { describe, expect, expectTypeOf, it } from 'vitest';
import { defineNode, type NodeDef } from '../../../nodes/core/define-node.ts';
import { createRegistry } from '../../../nodes/core/registry.ts';
import type { SeedSpec } from '../../../nodes/core/scene.ts';
import type { Circle, Color, ImageRef, Vec2 } from '../../../nodes/core/values.ts';
import { evaluateGraph } from '../../../nodes/graph/evaluate.ts';
import { doc, node } from '../support/doc.ts';

const ring = defineNode({
  type: 'test-ring',
  version: 1,
  label: 'Ring',
  category: 'Geometry',
  color: '#000000',
  doc: 'A circle from a centre and radius, with a mode.',
  inputs: {
    center: { type: 'point', label: 'centre', default: [1, 2] },
    radius: { type: 'number', label: 'radius', default: 3 },
    picture: { type: 'image', label: 'picture', optional: true },
    seeds: { type: 'seed', label: 'seeds', optional: true },
  },
  outputs: {
    circle: { type: 'circle', label: 'circle' },
    rim: { type: 'point', label: 'rim', optional: true },
  },
  params: {
    mode: { kind: 'enum', default: 'whole', options: ['whole', 'half'] },
    tint: { kind: 'color', default: '#ff0000' },
  },
  evaluate: ({ inputs, params }) => {
    expectTypeOf(inputs.center).toEqualTypeOf<Vec2>();
    expectTypeOf(inputs.radius).toEqualTypeOf<number>();
    expectTypeOf(inputs.picture).toEqualTypeOf<ImageRef | undefined>();
    expectTypeOf(inputs.seeds).toEqualTypeOf<readonly SeedSpec[]>();
    expectTypeOf(params.mode).toEqualTypeOf<'whole' | 'half'>();
    expectTypeOf(params.tint).toEqualTypeOf<Color>();
    const r = params.mode === 'half' ? inputs.radius / 2 : inputs.radius;
    return { outputs: { circle: { c: inputs.center, r } }, readout: `${inputs.seeds.length} seeds` };
  },
  overlay: (_ctx, out) => {
    expectTypeOf(out.circle).toEqualTypeOf<Circle>();
    expectTypeOf(out.rim).toEqualTypeOf<Vec2 | undefined>();
    return [{ shape: 'circle', circle: out.circle }];
  },
  // A failed node is asked for handles too: its outputs may all be missing.
  handles: (_ctx, out) => (out.circle ? [{ handle: 'center', at: out.circle.c }] : []),
  drag: (_handle, to) => ({ center: [...to] }),
});

/** Each member below must fail to compile; the rest of the definition is valid. */
const base = {
  type: 'test-bad',
  version: 1,
  label: 'Bad',
  category: 'Values',
  color: '#000000',
  doc: 'Type errors on purpose.',
  inputs: { x: { type: 'number', label: 'x', default: 1 } },
  outputs: { y: { type: 'number', label: 'y' } },
  params: { on: { kind: 'boolean', default: true } },
} as const;

defineNode({
  ...base,
  // @ts-expect-error: there is no input "z"
  evaluate: ({ inputs }) => ({ outputs: { y: inputs.z } }),
});

defineNode({
  ...base,
  // @ts-expect-error: there is no param "off"
  evaluate: ({ inputs, params }) => ({ outputs: { y: params.off ? inputs.x : 0 } }),
});

defineNode({
  ...base,
  // @ts-expect-error: output y is a number, not a point
  evaluate: () => ({ outputs: { y: [0, 0] as Vec2 } }),
});

defineNode({
  ...base,
  // @ts-expect-error: a misspelt output leaves the declared one (y) missing
  evaluate: ({ inputs }) => ({ outputs: { why: inputs.x } }),
});

defineNode({
  ...base,
  evaluate: ({ inputs }) => ({ outputs: { y: inputs.x } }),
  // @ts-expect-error: a drag may only set declared inputs and params
  drag: () => ({ nope: 1 }),
});

describe('defineNode', () => {
  it('a typed definition is stored erased in a registry and evaluates as declared', () => {
    const erased: NodeDef = ring;
    const registry = createRegistry([erased]);
    const ev = evaluateGraph(doc([node('n', 'test-ring', { mode: 'half', radius: 4 })]), registry);
    const n = ev.nodes.get('n');
    expect(n?.diagnostics).toEqual([]);
    expect(n?.outputs).toEqual({ circle: { c: [1, 2], r: 2 } });
    expect(n?.readout).toBe('0 seeds');
    expect(ev.scene.overlays.map((o) => o.shape)).toEqual([{ shape: 'circle', circle: { c: [1, 2], r: 2 } }]);
    expect(ev.scene.handles).toEqual([{ nodeId: 'n', handle: 'center', at: [1, 2] }]);
  });

  it('rejects an id that is not kebab-case', () => {
    expect(() => defineNode({ ...base, type: 'Not Kebab', evaluate: () => ({}) })).toThrow(/kebab-case/);
  });
});
