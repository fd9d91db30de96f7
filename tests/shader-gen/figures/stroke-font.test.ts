/** The PNG label font: every generator name has a glyph, glyphs stay in their box, and differ. */
import { describe, expect, it } from 'vitest';
import { ADVANCE, CAP_HEIGHT, hasGlyph, textStrokes } from '../../../shader-gen/figures/stroke-font.ts';

const LETTERS = [...'abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789'];

describe('stroke font', () => {
  it('draws every letter and digit a figure label can hold', () => {
    for (const ch of LETTERS) expect(hasGlyph(ch), ch).toBe(true);
  });

  it('keeps each glyph in its cell: 4 units wide, from the cap line to the descender', () => {
    for (const ch of LETTERS) {
      const lines = textStrokes(ch, [0, CAP_HEIGHT], CAP_HEIGHT);
      expect(lines.length, ch).toBeGreaterThan(0);
      for (const line of lines) {
        expect(line.length, ch).toBeGreaterThanOrEqual(2);
        for (const [x, y] of line) {
          expect(x, ch).toBeGreaterThanOrEqual(0);
          expect(x, ch).toBeLessThanOrEqual(4);
          expect(y, ch).toBeGreaterThanOrEqual(0);
          expect(y, ch).toBeLessThanOrEqual(8.5);
        }
      }
    }
  });

  it('gives every character its own shape, and advances along the baseline', () => {
    const shapes = LETTERS.map((ch) => JSON.stringify(textStrokes(ch, [0, 6], 6)));
    expect(new Set(shapes).size).toBe(LETTERS.length);
    const two = textStrokes('aa', [0, 6], 6);
    expect(two[two.length - 1][0][0] - two[0][0][0]).toBeCloseTo(ADVANCE, 9);
    // Scaled: capitals capPx tall.
    const big = textStrokes('I', [10, 40], 30).flat();
    expect(Math.min(...big.map((p) => p[1]))).toBeCloseTo(10, 9);
    expect(Math.max(...big.map((p) => p[1]))).toBeCloseTo(40, 9);
  });
});
