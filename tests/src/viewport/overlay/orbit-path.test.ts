import { describe, expect, it } from 'vitest';
import { MAX_DRAWN_STEPS, placeOrbit } from '../../../../src/viewport/overlay/orbit-path.ts';
import { clipSegmentToRect } from '../../../../src/viewport/overlay/screen.ts';

// 400 × 400 px showing [−2, 2]²: 100 px per world unit, the origin at (200, 200), y up.
const screen = { view: { center: [0, 0] as [number, number], scale: 4 }, width: 400, height: 400 };
const step = (x: number, y: number) => ({ at: [x, y] as [number, number], color: '#fff' });

describe('placeOrbit', () => {
  it('places the start, numbered markers and the segments between successive points', () => {
    const o = placeOrbit([0, 0], [step(1, 0), step(1, 1)], screen);
    expect(o.start).toEqual([200, 200]);
    expect(o.markers).toEqual([
      { step: 1, at: [300, 200], color: '#fff' },
      { step: 2, at: [300, 100], color: '#fff' },
    ]);
    expect(o.segments.map((s) => [s.a, s.b])).toEqual([
      [
        [200, 200],
        [300, 200],
      ],
      [
        [300, 200],
        [300, 100],
      ],
    ]);
    expect(o.omitted).toBe(0);
  });

  it('draws no marker far outside the view but clips its segments to the pane', () => {
    const o = placeOrbit([0, 0], [step(1e18, 0), step(1, 0)], screen);
    expect(o.markers.map((m) => m.step)).toEqual([2]);
    for (const s of o.segments) for (const p of [s.a, s.b]) expect(Math.abs(p[0])).toBeLessThan(500);
    expect(o.segments).toHaveLength(2);
  });

  it(`caps the drawn steps at ${MAX_DRAWN_STEPS} and says how many were left out`, () => {
    const many = Array.from({ length: MAX_DRAWN_STEPS + 50 }, (_, i) => step((i % 2) * 0.5, 0));
    const o = placeOrbit([0, 0], many, screen);
    expect(o.markers).toHaveLength(MAX_DRAWN_STEPS);
    expect(o.omitted).toBe(50);
  });
});

describe('clipSegmentToRect', () => {
  it('keeps a segment inside, cuts one that leaves, and drops one that misses', () => {
    expect(clipSegmentToRect([10, 10], [20, 20], 100, 100, 0)).toEqual([
      [10, 10],
      [20, 20],
    ]);
    expect(clipSegmentToRect([50, 50], [250, 50], 100, 100, 0)).toEqual([
      [50, 50],
      [100, 50],
    ]);
    expect(clipSegmentToRect([150, 150], [250, 250], 100, 100, 0)).toBeNull();
  });
});
