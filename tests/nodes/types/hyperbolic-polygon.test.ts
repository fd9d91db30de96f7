import { describe, expect, it } from 'vitest';
import type { SceneElement } from '../../../nodes/core/scene.ts';
import { interpret } from '../../../shader-gen/interpret.ts';
import { checkDefaults, codes, evalNode } from '../support/eval-node.ts';

describe('hyperbolic-polygon node', () => {
  it('defaults: pentagons with 60° angles, six at a vertex; the unit disk as boundary', () => {
    const r = checkDefaults('hyperbolic-polygon');
    expect(r.readout).toBe('{5, 6}: 5-gons with 60° angles, 6 at each vertex');
    expect(r.outputs!.elements as SceneElement[]).toHaveLength(5);
    expect(r.outputs!.boundary).toEqual({ c: [0, 0], r: 1 });
    const scene = { elements: r.outputs!.elements as SceneElement[], maxIterations: 200 };
    expect(interpret(scene, [0, 0])).toMatchObject({ depth: 0, escaped: true });
    // Points well inside the disk reach the central pentagon.
    for (const p of [
      [0.6, 0.1],
      [-0.3, 0.7],
      [0.2, -0.85],
    ] as const) {
      expect(interpret(scene, p).escaped).toBe(true);
    }
  });

  it('rejects Euclidean and spherical polygons', () => {
    const square = evalNode('hyperbolic-polygon', { n: 4, q: 2 });
    expect(codes(square)).toEqual(['KF303']);
    expect(square.diagnostics[0].message).toMatch(/Euclidean/);
    expect(evalNode('hyperbolic-polygon', { n: 3, q: 2 }).diagnostics[0].message).toMatch(/spherical/);
  });
});
