import { describe, expect, it } from 'vitest';
import { panelPlace } from '../../../../src/app/inspect/panel-place.ts';

/** The panel's horizontal and vertical extent in a `w` × `h` pane, at its largest. */
function extent(p: ReturnType<typeof panelPlace>, w: number) {
  const left = p.left ?? w - (p.right ?? 0) - (p.width ?? 0);
  const right = p.width !== undefined ? left + p.width : w - (p.right ?? 0);
  return { left, right, top: p.top, bottom: p.top + p.maxHeight };
}

describe('the Explain-this-pixel panel place', () => {
  it('never covers the clicked point, in wide and narrow panes', () => {
    for (const [w, h] of [
      [320, 650],
      [640, 650],
      [1200, 800],
      [390, 700],
    ]) {
      for (let fx = 0.05; fx < 1; fx += 0.1) {
        for (let fy = 0.1; fy < 1; fy += 0.1) {
          const [x, y] = [fx * w, fy * h];
          const e = extent(panelPlace([x, y], w, h), w);
          const covered = x >= e.left && x <= e.right && y >= e.top && y <= e.bottom;
          expect(covered, `${w}×${h} at ${x.toFixed(0)},${y.toFixed(0)}`).toBe(false);
          expect(e.left).toBeGreaterThanOrEqual(0);
          expect(e.right).toBeLessThanOrEqual(w);
        }
      }
    }
  });

  it('sits beside the point, readable, when the pane is wide enough', () => {
    const p = panelPlace([900, 400], 1200, 800);
    expect(p.left).toBe(12);
    expect(p.width).toBe(390);
  });
});
