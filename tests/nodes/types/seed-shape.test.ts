import { describe, expect, it } from 'vitest';
import { seedShapeValue } from '../../../shader-gen/seeds.ts';
import { checkDefaults, codes, evalNode } from '../support/eval-node.ts';

describe('seed-shape node', () => {
  it('gives a flower seed by default: inside at its centre, outside beyond its petals', () => {
    const seed = checkDefaults('seed-shape').outputs!.seed as Parameters<typeof seedShapeValue>[0];
    expect(seed).toMatchObject({ kind: 'shape', numbers: [0.12, 5, 0.35, 0], points: [0, 0, 1, 0] });
    expect(seedShapeValue(seed, 0, 0)).toBeLessThan(0);
    expect(seedShapeValue(seed, 0.12 * 1.35 + 0.01, 0)).toBeGreaterThan(0); // the petal's tip is on +x
    expect(seedShapeValue(seed, 0.15, 0)).toBeLessThan(0);
    expect(seedShapeValue(seed, 0, 0.15)).toBeGreaterThan(0); // between petals
  });

  it('carries the time, so an animated shape needs no new program', () => {
    const seed = evalNode('seed-shape', { formula: 'length(z) - t' }, 0.5).outputs!.seed as Parameters<
      typeof seedShapeValue
    >[0];
    expect(seed.numbers[3]).toBe(0.5);
    expect(seedShapeValue(seed, 0.4, 0)).toBeLessThan(0);
  });

  it('refuses a formula that does not check, or does not give a number, with KF327', () => {
    expect(codes(evalNode('seed-shape', { formula: 'length(z) -' }))).toEqual(['KF327']);
    const point = evalNode('seed-shape', { formula: 'z * 2' });
    expect(codes(point)).toEqual(['KF327']);
    expect(point.diagnostics[0]!.message).toContain('not a point');
  });
});
