import { describe, expect, it } from 'vitest';
import type { View } from '../../../nodes/core/scene.ts';
import type { FigureLayer } from '../../../shader-gen/figures/layer.ts';
import { paintFigures } from '../../../shader-gen/figures/paint.ts';

const view: View = { center: [0, 0], scale: 2 };
const blank = () => ({ width: 40, height: 40, data: new Uint8ClampedArray(40 * 40 * 4) });
const red = (img: ReturnType<typeof blank>, x: number, y: number) => img.data[(y * img.width + x) * 4];

describe('paintFigures', () => {
  it('paints a horizontal stroke along its row (y up in the world, row 0 at the top) and nothing far off', () => {
    const img = blank();
    const layer: FigureLayer = {
      strokes: [
        {
          points: [
            [-0.5, 0.5],
            [0.5, 0.5],
          ],
          color: [1, 0, 0],
          width: 2,
        },
      ],
      dots: [],
      labels: [],
      notes: [],
    };
    paintFigures(img, view, layer);
    // World y = 0.5 is pixel y = 30 from the bottom: rows 9 and 10 from the top.
    expect(red(img, 20, 9)).toBeGreaterThan(200);
    expect(red(img, 20, 10)).toBeGreaterThan(200);
    expect(red(img, 20, 30)).toBe(0);
    expect(red(img, 2, 10)).toBe(0);
  });

  it('paints a dot as a disk of its radius', () => {
    const img = blank();
    paintFigures(img, view, {
      strokes: [],
      dots: [{ at: [0, 0], color: [1, 1, 1], r: 3 }],
      labels: [],
      notes: [],
    });
    expect(red(img, 20, 20)).toBe(255);
    expect(red(img, 26, 20)).toBe(0);
  });
});
