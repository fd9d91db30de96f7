import { describe, expect, it } from 'vitest';
import type { ReflectionElement } from '../../../nodes/core/scene.ts';
import { interpret } from '../../../shader-gen/interpret.ts';
import { checkDefaults, defOf, evalNode } from '../support/eval-node.ts';

describe('k-mirror node', () => {
  it('keeps exactly the wedge of angle π/k from the start direction', () => {
    const r = checkDefaults('k-mirror');
    expect(r.readout).toBe('*55: 10 wedges of 36°');
    const elements = r.outputs!.elements as ReflectionElement[];
    const scene = { elements, maxIterations: 100 };
    const at = (deg: number) => {
      const t = (deg * Math.PI) / 180;
      return interpret(scene, [Math.cos(t), Math.sin(t)]);
    };
    expect(at(18).depth).toBe(0); // inside the 36° wedge
    expect(at(54).depth).toBe(1); // one mirror away
    expect(at(-18).depth).toBe(1);
    expect(at(180 + 18).depth).toBe(5); // the opposite wedge: 5 mirrors across
    for (const deg of [10, 100, 200, 300]) expect(at(deg).escaped).toBe(true);
  });

  it('draws both mirrors and turns with the direction handle', () => {
    const def = defOf('k-mirror');
    const r = evalNode('k-mirror', { k: 4, center: [1, 0] });
    expect(def.overlay!(r.ctx!, r.outputs!)).toHaveLength(2);
    expect(def.drag!('direction', [1, 2], r.ctx!)).toEqual({ angle: 90 });
  });
});
