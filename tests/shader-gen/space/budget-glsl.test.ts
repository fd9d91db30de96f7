/**
 * Which programs carry the GLSL bound of a walk out of budget (shader-gen/space/glsl/budget.glsl.ts):
 * those with a sphairahedron tile as a seed (the tiling steps), not the others, whose frames would
 * pay for its code in software WebGL (docs/math-3d.md "The bound when the budget runs out"). GPU =
 * CPU for the tiling steps: tests/parity/trace3d-parity.test.ts; glslang: compile-3d.test.ts.
 */
import { describe, expect, it } from 'vitest';
import { compile3d } from '../../../shader-gen/space/compile-3d.ts';
import { exampleScenes3d } from './scenes-3d.ts';

const examples = exampleScenes3d();

describe('the GLSL budget bound', () => {
  it('is in every program of the tiling steps, in the march, for the probe and the colours alike', () => {
    for (const name of ['fig27-tiling-steps', 'fig28b-tiling-step-2', 'fig28d-tiling-step-20']) {
      for (const variant of ['probe', 'color'] as const) {
        const source = compile3d(examples[name]!, { variant }).source;
        expect(source, name).toContain('float walkBudget(vec3 start, float seedDe, float floorDe)');
        expect(source, name).toMatch(
          /if \(info\.x < eps\) return true;\n\s*de = budgetedDe\(o \+ d \* t, info, de\);/,
        );
      }
    }
  });

  it('is left out where no seed is a tile (Figs. 11, 26, 37: §8’s bound alone)', () => {
    for (const name of [
      'fig11-sphere-inversion-fractal',
      'fig26-quasi-sphere',
      'fig37-indras-bubbles-mirror',
    ]) {
      expect(examples[name]!.seeds.some((s) => s.kind === 'tile')).toBe(false);
      expect(compile3d(examples[name]!, { variant: 'probe' }).source, name).not.toContain('walkBudget');
    }
  });

  it('keeps the source when max iterations changes (the step control is a uniform)', () => {
    const scene = examples['fig28b-tiling-step-2']!;
    expect(compile3d({ ...scene, maxIterations: 5 }).source).toBe(compile3d(scene).source);
  });
});
