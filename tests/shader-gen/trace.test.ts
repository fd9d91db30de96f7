/**
 * The trace of one IIS run ("Explain this pixel"): its steps on hand-made scenes, its stop reasons,
 * and — property — that its depth, final point and scale are interpret()'s for random points of
 * several examples (it observes the interpreter's own loop, so they must be equal, not close).
 */
import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import type { SceneElement } from '../../nodes/core/scene.ts';
import type { Vec2 } from '../../nodes/core/values.ts';
import type { IisState } from '../../shader-gen/elements/element-kind.ts';
import { ELEMENTS } from '../../shader-gen/elements/index.ts';
import { interpret } from '../../shader-gen/interpret.ts';
import { type IisTrace, trace, tracePicture } from '../../shader-gen/trace.ts';
import { loadExample } from '../support/examples.ts';
import { inv, rectangle, scene } from './interpret-scenes.ts';
import { makeScene } from './support/scenes.ts';

/** Replays every recorded step with the element's own CPU step: each must lead where the trace says. */
function replay(elements: readonly SceneElement[], t: IisTrace): void {
  const st: IisState = { x: t.start[0], y: t.start[1], s: 1, depth: 0 };
  for (const step of t.steps) {
    const e = elements[step.element];
    expect(step.nodeId).toBe(e.nodeId);
    // The applied element is the first that holds the point (docs/math.md "The IIS loop").
    for (let i = 0; i < step.element; i++)
      expect(ELEMENTS[elements[i].kind].cpu.inside(elements[i] as never, st.x, st.y)).toBe(false);
    expect(ELEMENTS[e.kind].cpu.step(e as never, st)).toBe(true);
    expect([st.x, st.y, st.s, st.depth]).toEqual([step.x, step.y, step.factor, step.depth]);
  }
}

describe('trace', () => {
  it('records each reflection of a *2222 rectangle and ends in the tile', () => {
    const s = scene(rectangle(1, 1));
    const t = trace(s, [2.5, -0.5]);
    expect(t.stop).toBe('fundamental-domain');
    expect(t.escaped).toBe(true);
    expect(t.depth).toBe(3);
    // 2.5 → −0.5 in x = 1 (mirror 1), → 0.5 in x = 0 (mirror 0), then y: −0.5 → 0.5 (mirror 2).
    expect(t.steps.map((s) => s.element)).toEqual([1, 0, 2]);
    expect(t.final[0]).toBeCloseTo(0.5, 12);
    expect(t.final[1]).toBeCloseTo(0.5, 12);
    expect(t.steps.map((s) => s.depth)).toEqual([1, 2, 3]);
    replay(s.elements, t);
  });

  it('accumulates the inversion factor r²/|p − c|²', () => {
    const s = scene([inv([0, 0], 1, 'circle')]);
    const t = trace(s, [0.5, 0]);
    expect(t.steps).toEqual([{ element: 0, nodeId: 'circle', depth: 1, x: 2, y: 0, factor: 4 }]);
    expect(t.scale).toBe(4);
    expect(t.stop).toBe('fundamental-domain');
  });

  it('a point in the tile takes no step', () => {
    const t = trace(scene(rectangle(1, 1)), [0.25, 0.75]);
    expect(t).toMatchObject({
      steps: [],
      depth: 0,
      stop: 'fundamental-domain',
      final: [0.25, 0.75],
      scale: 1,
    });
  });

  it('stops at the limit when still inside an element at maxIterations', () => {
    const t = trace(scene(rectangle(1, 1), 2), [5.5, 0.5]);
    expect(t.stop).toBe('limit');
    expect(t.escaped).toBe(false);
    expect(t.depth).toBe(2);
    expect(t.steps).toHaveLength(2);
  });

  it('stops in an orbit seed, at the start of the step that finds it', () => {
    const seed = { kind: 'disk', nodeId: 'seed', c: [0.5, 0.5], r: 0.1, color: [1, 0, 0] } as const;
    const s = makeScene(rectangle(1, 1), { tile: { seeds: [seed] } });
    const t = tracePicture(s, [2.5, 0.5]);
    expect(t.stop).toBe('seed');
    expect(t.seed).toBe(0);
    expect(t.escaped).toBe(false);
    expect(t.depth).toBe(2);
    // Without seeds (what `kleinflow sample` runs) the same point just reaches the tile.
    expect(trace(s, [2.5, 0.5]).stop).toBe('fundamental-domain');
  });

  it('does not run outside the clip disk', () => {
    const s = makeScene(rectangle(1, 1), { clip: { c: [0, 0], r: 2 } });
    const t = tracePicture(s, [2.5, 0.5]);
    expect(t).toMatchObject({ stop: 'clipped', steps: [], depth: 0, escaped: false, seed: -1 });
    expect(tracePicture(s, [1.5, 0.5]).stop).toBe('fundamental-domain');
  });
});

const uniform = fc.noBias(fc.integer({ min: -1_000_000, max: 1_000_000 })).map((k) => k / 1e6);

describe('trace = interpret (property, fixed seed)', () => {
  const names = [
    'hyperbolic-237',
    'apollonian-gasket',
    'schottky-pair',
    'loxodromic-spiral',
    'glide-reflection-frieze',
    'spiral-similarity-pearls',
    'schottky-matrix-generators',
  ];
  for (const name of names) {
    it(name, () => {
      const { scene: s } = loadExample(name);
      const half = s.view.scale * 0.75;
      const points = fc
        .tuple(uniform, uniform)
        .map(([u, v]): Vec2 => [s.view.center[0] + u * half, s.view.center[1] + v * half]);
      fc.assert(
        fc.property(points, (p) => {
          const t = trace(s, p);
          const r = interpret(s, p);
          expect({ depth: t.depth, final: t.final, scale: t.scale, escaped: t.escaped }).toEqual(r);
          expect(t.stop).toBe(r.escaped ? 'fundamental-domain' : 'limit');
          const last = t.steps.at(-1);
          if (last) expect([last.x, last.y, last.factor, last.depth]).toEqual([...r.final, r.scale, r.depth]);
          else expect(r.depth).toBe(0);
          replay(s.elements, t);
        }),
        { seed: 16, numRuns: 60 },
      );
    });
  }
});
