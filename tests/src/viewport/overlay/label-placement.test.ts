/**
 * Overlay label placement: labels never overlap each other or leave the view, a free label keeps
 * its usual up-right place, crowded ones move round their anchor, priority decides who keeps it.
 */
import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import {
  type Box,
  boxesIntersect,
  candidateBox,
  circleCandidates,
  LABEL_MARGIN,
  type LabelRequest,
  placeLabels,
  pointCandidates,
} from '../../../../src/viewport/overlay/label-placement.ts';

const RUNS = { seed: 7, numRuns: 300 } as const;
const view = { width: 400, height: 300 };

const pointLabel = (id: string, at: [number, number], priority = 0, width = 40): LabelRequest => ({
  id,
  width,
  height: 16,
  gap: 8,
  priority,
  candidates: pointCandidates(at),
});

describe('candidate boxes', () => {
  it('sit gap pixels from the anchor in the candidate direction', () => {
    const [ne, se, nw, sw, e, w, n, s] = pointCandidates([100, 100]).map((c) => candidateBox(c, 40, 16, 8));
    expect(ne).toEqual({ x: 108, y: 76, width: 40, height: 16 });
    expect(se).toEqual({ x: 108, y: 108, width: 40, height: 16 });
    expect(nw).toEqual({ x: 52, y: 76, width: 40, height: 16 });
    expect(sw).toEqual({ x: 52, y: 108, width: 40, height: 16 });
    expect(e).toEqual({ x: 108, y: 92, width: 40, height: 16 });
    expect(w).toEqual({ x: 52, y: 92, width: 40, height: 16 });
    expect(n).toEqual({ x: 80, y: 76, width: 40, height: 16 });
    expect(s).toEqual({ x: 80, y: 108, width: 40, height: 16 });
  });

  it('put a circle label on the rim, first at 45° up-right, pointing outward', () => {
    const [first, ...rest] = circleCandidates([100, 100], 50);
    expect(first.anchor[0]).toBeCloseTo(100 + 50 * Math.SQRT1_2);
    expect(first.anchor[1]).toBeCloseTo(100 - 50 * Math.SQRT1_2);
    expect(first.dir).toEqual([1, -1]);
    for (const c of rest) expect(Math.hypot(c.anchor[0] - 100, c.anchor[1] - 100)).toBeCloseTo(50);
  });
});

describe('placeLabels', () => {
  it('keeps a lone label in its usual place, up-right of its point', () => {
    const placed = placeLabels([pointLabel('a', [100, 100])], view);
    expect(placed.get('a')).toEqual({ x: 108, y: 76, width: 40, height: 16 });
  });

  it('moves a second label at the same point to another side instead of on top', () => {
    const placed = placeLabels([pointLabel('a', [100, 100]), pointLabel('b', [100, 100])], view);
    const a = placed.get('a')!;
    const b = placed.get('b')!;
    expect(boxesIntersect(a, b)).toBe(false);
    expect(b.y).toBeGreaterThan(a.y); // the next candidate: down-right
  });

  it('gives the higher priority its preferred place', () => {
    const placed = placeLabels([pointLabel('low', [100, 100]), pointLabel('high', [100, 100], 1)], view);
    expect(placed.get('high')).toEqual({ x: 108, y: 76, width: 40, height: 16 });
    expect(placed.get('low')).toBeDefined();
  });

  it('keeps a label near the right edge inside the view by putting it on the left', () => {
    const box = placeLabels([pointLabel('a', [390, 150])], view).get('a')!;
    expect(box.x + box.width).toBeLessThanOrEqual(view.width - LABEL_MARGIN);
    expect(box.x).toBe(390 - 8 - 40);
  });

  it('leaves out a label whose anchor is off the view, or that has no free place', () => {
    expect(placeLabels([pointLabel('off', [-20, 100])], view).size).toBe(0);
    const crowd = Array.from({ length: 12 }, (_, i) => pointLabel(`p${i}`, [200, 150], 0, 120));
    const placed = placeLabels(crowd, view);
    expect(placed.size).toBeGreaterThan(1);
    expect(placed.size).toBeLessThan(12);
  });

  it('prefers a place off the drawn points when there is one', () => {
    const dot: Box = { x: 110, y: 78, width: 8, height: 8 }; // on the up-right candidate
    const box = placeLabels([pointLabel('a', [100, 100])], view, [dot]).get('a')!;
    expect(boxesIntersect(box, dot)).toBe(false);
  });

  it('steps a little farther out when every near place covers a drawn point', () => {
    // Dots hugging the point on all sides (a crowd of handles around a small circle).
    const ring: Box[] = [-1, 0, 1].flatMap((i) =>
      [-1, 0, 1].map((j) => ({ x: 100 + 30 * i - 20, y: 100 + 20 * j - 12, width: 40, height: 24 })),
    );
    const box = placeLabels([pointLabel('a', [100, 100])], view, ring).get('a')!;
    expect(ring.some((o) => boxesIntersect(box, o))).toBe(true); // nothing clear: the usual place
    const sparse: Box[] = pointCandidates([100, 100]).map((c) => candidateBox(c, 4, 4, 10));
    const far = placeLabels([pointLabel('a', [100, 100])], view, sparse).get('a')!;
    expect(sparse.some((o) => boxesIntersect(far, o))).toBe(false);
    expect(far.x).toBe(100 + 8 + 14);
  });

  it('never overlaps two labels nor leaves the view (random points, circles and sizes)', () => {
    const label = fc.record({
      at: fc.tuple(
        fc.double({ min: -50, max: 450, noNaN: true }),
        fc.double({ min: -50, max: 350, noNaN: true }),
      ),
      r: fc.option(fc.double({ min: 1, max: 300, noNaN: true }), { nil: undefined }),
      width: fc.integer({ min: 8, max: 160 }),
      priority: fc.integer({ min: 0, max: 2 }),
    });
    fc.assert(
      fc.property(fc.array(label, { maxLength: 30 }), (labels) => {
        const requests = labels.map(
          (l, i): LabelRequest => ({
            id: String(i),
            width: l.width,
            height: 16,
            gap: 6,
            priority: l.priority,
            candidates: l.r === undefined ? pointCandidates(l.at) : circleCandidates(l.at, l.r),
          }),
        );
        const boxes = [...placeLabels(requests, view).values()];
        for (const [i, a] of boxes.entries()) {
          expect(a.x).toBeGreaterThanOrEqual(LABEL_MARGIN);
          expect(a.y).toBeGreaterThanOrEqual(LABEL_MARGIN);
          expect(a.x + a.width).toBeLessThanOrEqual(view.width - LABEL_MARGIN);
          expect(a.y + a.height).toBeLessThanOrEqual(view.height - LABEL_MARGIN);
          for (const b of boxes.slice(i + 1)) expect(boxesIntersect(a, b, LABEL_MARGIN)).toBe(false);
        }
      }),
      RUNS,
    );
  });
});
