import { describe, expect, it } from 'vitest';
import type { Seed3d } from '../../../nodes/core/scene-3d.ts';
import { SLOPE_MARGIN } from '../../../nodes/types/seed-solid.ts';
import { seedDistance } from '../../../shader-gen/space/seeds-3d.ts';
import { checkDefaults, codes, evalNode } from '../support/eval-node.ts';

type Solid = Extract<Seed3d, { kind: 'formula' }>;
const solidOf = (r: ReturnType<typeof evalNode>) => r.outputs!.seed as Solid;

describe('seed-solid node', () => {
  it('gives a torus by default: a true distance, used as it is (slope 1, no warning)', () => {
    const r = checkDefaults('seed-solid');
    const seed = solidOf(r);
    expect(seed).toMatchObject({
      kind: 'formula',
      center: [0, 0, 0],
      radius: 0.5,
      numbers: [0.32, 0.1, 0],
      slope: 1,
    });
    expect(r.diagnostics).toEqual([]);
    expect(seedDistance(seed, 0.32, 0, 0)).toBeCloseTo(-0.1, 12); // in the tube
    expect(seedDistance(seed, 0, 0, 0)).toBeCloseTo(0.22, 12); // the hole
    expect(seedDistance(seed, 0, 0.42, 0)).toBeCloseTo(0, 12); // on the rim
  });

  it('a formula steeper than a distance is divided by more than its sampled slope, with KF330', () => {
    const r = evalNode('seed-solid', { formula: '4 * (length(point(length(point(x, y)) - a, z)) - b)' });
    expect(codes(r, 'warning')).toEqual(['KF330']);
    const seed = solidOf(r);
    expect(seed.slope).toBeGreaterThan(4 * SLOPE_MARGIN * 0.95);
    expect(r.diagnostics[0]!.message).toMatch(/slope reaches 4(\.0*)?\b.*divides it by 5/);
    // the same surface, and the bound is the true distance's or less
    expect(seedDistance(seed, 0, 0.42, 0)).toBeCloseTo(0, 12);
    expect(seedDistance(seed, 0, 0, 0)).toBeLessThanOrEqual(0.22);
  });

  it('warns where the formula is not a number in its ball (KF331)', () => {
    const r = evalNode('seed-solid', { formula: 'sqrt(x) - 0.5' });
    expect(codes(r, 'warning')).toContain('KF331');
    expect(r.diagnostics.find((d) => d.code === 'KF331')!.message).toMatch(
      /not a number at some points.*\(-/,
    );
  });

  it('refuses an empty solid, a formula that does not check or is not a number, and a bad ball', () => {
    expect(codes(evalNode('seed-solid', { formula: 'a + 1' }))).toEqual(['KF303']);
    expect(evalNode('seed-solid', { formula: 'a + 1' }).diagnostics[0]!.message).toMatch(/nowhere negative/);
    expect(codes(evalNode('seed-solid', { formula: 'x +' }))).toEqual(['KF327']);
    expect(codes(evalNode('seed-solid', { formula: 'point(x, y)' }))).toEqual(['KF327']);
    // t is not among a solid's names
    expect(evalNode('seed-solid', { formula: 'x - t' }).diagnostics[0]!.message).toContain('t');
    expect(codes(evalNode('seed-solid', { radius: 0 }))).toEqual(['KF303']);
  });
});
