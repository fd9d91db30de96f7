/** Panning the inspected node into view: the smallest move that shows it, none when it shows. */
import { describe, expect, it } from 'vitest';
import { shiftIntoView } from '../../../src/editor/keep-in-view.ts';

describe('shiftIntoView', () => {
  it('does not move a span that is already inside', () => {
    expect(shiftIntoView(20, 100, 400, 16)).toBe(0);
    expect(shiftIntoView(16, 368, 400, 16)).toBe(0);
  });
  it('moves a span cut by the far edge back by exactly the overhang', () => {
    expect(shiftIntoView(350, 100, 400, 16)).toBe(-66);
  });
  it('moves a span cut by the near edge forward', () => {
    expect(shiftIntoView(-40, 100, 400, 16)).toBe(56);
  });
  it('shows the start of a span longer than the room', () => {
    expect(shiftIntoView(100, 1000, 400, 16)).toBe(-84);
  });
});
