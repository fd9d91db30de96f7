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

  it('paints a label as letters of its colour, outlined, right of and above its point', () => {
    const img = blank();
    const label = (text: string) => ({
      strokes: [],
      dots: [],
      labels: [{ at: [-0.5, -0.5] as const, text, color: [0, 1, 0] as const }],
      notes: [],
    });
    paintFigures(img, view, label('A'));
    // The point is pixel (10, 30); the letter sits in x 14–21, y 16–26 (10 px capitals on a 4 px
    // raised baseline): green there, nothing left of or below the point.
    const green = (x: number, y: number) => img.data[(y * img.width + x) * 4 + 1];
    let inside = 0;
    for (let y = 16; y <= 26; y++) for (let x = 14; x <= 21; x++) if (green(x, y) > 128) inside++;
    expect(inside).toBeGreaterThan(8);
    for (let y = 0; y < 40; y++) for (let x = 0; x < 10; x++) expect(img.data[(y * 40 + x) * 4 + 3]).toBe(0);
    for (let y = 31; y < 40; y++) for (let x = 0; x < 40; x++) expect(img.data[(y * 40 + x) * 4 + 3]).toBe(0);
    // The outline: dark, opaque pixels around the green strokes.
    let outline = 0;
    for (let i = 0; i < img.data.length; i += 4)
      if (img.data[i + 3] > 200 && img.data[i + 1] < 60 && img.data[i] === 0) outline++;
    expect(outline).toBeGreaterThan(10);
    // Different letters paint differently.
    const other = blank();
    paintFigures(other, view, label('b'));
    expect(Buffer.from(other.data).equals(Buffer.from(img.data))).toBe(false);
  });
});
