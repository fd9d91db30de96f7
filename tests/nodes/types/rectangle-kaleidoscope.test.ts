import { describe, expect, it } from 'vitest';
import type { SceneElement } from '../../../nodes/core/scene.ts';
import { interpret } from '../../../shader-gen/interpret.ts';
import { checkDefaults, codes, defOf, evalNode } from '../support/eval-node.ts';

describe('rectangle-kaleidoscope node', () => {
  it('tiles with the rectangle; depth counts the mirrors crossed', () => {
    const r = evalNode('rectangle-kaleidoscope', { corner: [0, 0], width: 2, height: 1 });
    const scene = { elements: r.outputs!.elements as SceneElement[], maxIterations: 100 };
    expect(interpret(scene, [0.5, 0.5]).depth).toBe(0);
    const far = interpret(scene, [5.5, -2.5]); // 2 vertical + 3 horizontal mirrors away
    expect(far.depth).toBe(5);
    expect(far.final[0]).toBeCloseTo(1.5, 12); // 5.5 → fold by 4 → 1.5
    expect(far.final[1]).toBeCloseTo(0.5, 12); // −2.5 → reflected 3 times → 0.5
    checkDefaults('rectangle-kaleidoscope');
  });

  it('rejects an empty rectangle; the opposite-corner handle resizes it', () => {
    expect(codes(evalNode('rectangle-kaleidoscope', { width: 0 }))).toEqual(['KF303']);
    const def = defOf('rectangle-kaleidoscope');
    const r = evalNode('rectangle-kaleidoscope', { corner: [0, 0], width: 2, height: 1 });
    expect(def.overlay!(r.ctx!, r.outputs!)).toHaveLength(4);
    expect(def.drag!('opposite', [3, 2], r.ctx!)).toEqual({ width: 3, height: 2 });
    expect(def.drag!('opposite', [-3, 2], r.ctx!).width).toBeGreaterThan(0);
  });
});
