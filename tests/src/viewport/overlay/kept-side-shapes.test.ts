import { describe, expect, it } from 'vitest';
import type { SceneElement } from '../../../../nodes/core/scene.ts';
import { BAND_PX, keptSideShapes } from '../../../../src/viewport/overlay/kept-side-shapes.ts';

const screen = { view: { center: [0, 0] as [number, number], scale: 4 }, width: 400, height: 400 };

describe('kept-side shapes', () => {
  it('a line mirror keeping its upper side is hatched just below the line, and discards the lower half', () => {
    const e: SceneElement = { kind: 'reflection', nodeId: 'm', q: [0, 0], n: [0, 1] };
    const [s] = keptSideShapes([e], screen);
    if (s.kind !== 'line') throw new Error('expected a line');
    // World y = 0 is the pane's middle row (CSS y = 200); y grows downwards on screen.
    const ys = s.band.map((p) => p[1]);
    expect(Math.min(...ys)).toBeCloseTo(200);
    expect(Math.max(...ys)).toBeCloseTo(200 + BAND_PX);
    const dy = s.discarded.map((p) => p[1]);
    expect(Math.min(...dy)).toBeCloseTo(200);
    expect(Math.max(...dy)).toBeCloseTo(400);
  });

  it('flipping the normal moves the hatching to the other side', () => {
    const e: SceneElement = { kind: 'reflection', nodeId: 'm', q: [0, 0], n: [0, -1] };
    const [s] = keptSideShapes([e], screen);
    if (s.kind !== 'line') throw new Error('expected a line');
    expect(Math.min(...s.band.map((p) => p[1]))).toBeCloseTo(200 - BAND_PX);
    expect(Math.max(...s.discarded.map((p) => p[1]))).toBeCloseTo(200);
  });

  it('a circle mirror is drawn in pixels; other elements and lines off the pane draw nothing', () => {
    const shapes = keptSideShapes(
      [
        { kind: 'inversion', nodeId: 'c', c: [0, 0], r: 1 },
        { kind: 'reflection', nodeId: 'far', q: [0, 50], n: [0, 1] },
        { kind: 'rotation', nodeId: 'r', c: [0, 0], b1: [1, 0], order: 3 },
      ],
      screen,
    );
    expect(shapes).toEqual([{ kind: 'circle', nodeId: 'c', c: [200, 200], r: 100, keepInside: false }]);
    const [flipped] = keptSideShapes([{ kind: 'outer-inversion', nodeId: 'c', c: [0, 0], r: 1 }], screen);
    expect(flipped).toEqual({ kind: 'circle', nodeId: 'c', c: [200, 200], r: 100, keepInside: true });
  });
});
