/** The 3D seeds: seed-sphere and seed-box — their Seed3d, read-outs and bad input. */
import { describe, expect, it } from 'vitest';
import { seedSamplePoints, seedSignedDistance } from '../../../nodes/core/seed-3d.ts';
import { evaluateGraph } from '../../../nodes/graph/evaluate.ts';
import { registry } from '../../../nodes/types/index.ts';
import { doc, node } from '../support/doc.ts';

const alone = (type: string, params: Record<string, unknown> = {}) => {
  const result = evaluateGraph(doc([node('n', type, params)]), registry).nodes.get('n')!;
  return { ...result, messages: result.diagnostics.map((d) => `${d.code} ${d.message}`) };
};

describe('seed-sphere', () => {
  it('makes a sphere seed with its colour (sRGB 0…1)', () => {
    expect(alone('seed-sphere', { center: [1, 2, 3], radius: 0.25, color: '#ff0000' }).outputs?.seed).toEqual(
      {
        kind: 'sphere',
        nodeId: 'n',
        sphere: { center: [1, 2, 3], radius: 0.25 },
        color: [1, 0, 0],
      },
    );
  });

  it('refuses a radius ≤ 0', () => {
    expect(alone('seed-sphere', { radius: -0.5 }).messages).toEqual([
      "KF303 the seed sphere's radius must be positive, got -0.5",
    ]);
  });
});

describe('seed-box', () => {
  it('makes a box seed', () => {
    const r = alone('seed-box', { center: [0, 0, 1], halfSize: [0.5, 0.25, 1] });
    expect(r.outputs?.seed).toMatchObject({
      kind: 'box',
      nodeId: 'n',
      center: [0, 0, 1],
      halfSize: [0.5, 0.25, 1],
    });
    expect(r.readout).toBe('half size (0.5, 0.25, 1)');
  });

  it('refuses a half size that is not positive along every axis', () => {
    expect(alone('seed-box', { halfSize: [1, 0, 1] }).messages).toEqual([
      'KF303 the box needs a positive half size along x, y and z, got (1, 0, 1)',
    ]);
  });
});

describe('seed distance and sample points', () => {
  const box = { kind: 'box', nodeId: 'b', center: [1, 1, 1], halfSize: [1, 2, 3], color: [1, 1, 1] } as const;
  const ball = {
    kind: 'sphere',
    nodeId: 's',
    sphere: { center: [0, 0, 0], radius: 2 },
    color: [1, 1, 1],
  } as const;

  it('box: exact outside (to a face, an edge, a corner) and minus the nearest face inside', () => {
    expect(seedSignedDistance(box, [3, 1, 1])).toBeCloseTo(1, 12);
    expect(seedSignedDistance(box, [3, 4, 1])).toBeCloseTo(Math.SQRT2, 12);
    expect(seedSignedDistance(box, [3, 4, 5])).toBeCloseTo(Math.sqrt(3), 12);
    expect(seedSignedDistance(box, [1, 1, 1])).toBeCloseTo(-1, 12);
  });

  it('sphere: |x − c| − r', () => {
    expect(seedSignedDistance(ball, [0, 3, 4])).toBe(3);
  });

  it('stand-in points lie on or in the seed', () => {
    for (const seed of [box, ball]) {
      const pts = seedSamplePoints(seed);
      expect(pts.length).toBeGreaterThanOrEqual(7);
      for (const p of pts) expect(seedSignedDistance(seed, p)).toBeLessThanOrEqual(1e-12);
    }
  });
});
