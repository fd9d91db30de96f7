/**
 * A single-stroke font for figure labels in PNGs (the painter has no text engine; SVG and the
 * overlay use the system font). Glyphs are polylines on a grid 4 units wide with the baseline at
 * y = 6 (y downwards): capitals span 0–6, lowercase x-height 2–6, descenders reach 8. Only what the
 * figures write is here: the letters a–z, A–Z (generator names, capitals for inverses) and digits.
 * Drawn by hand for this project, as plain as a label needs. Each glyph is written as its polylines
 * separated by "|", each a list of "x,y" points.
 */
import type { Vec2 } from '../../nodes/core/values.ts';

const O = '1,0 0,1 0,5 1,6 3,6 4,5 4,1 3,0 1,0';
const o = '1,2 0,3 0,5 1,6 3,6 4,5 4,3 3,2 1,2';
/** A bowl right of a stem at x = 0 (b, p) and left of one at x = 4 (a, d, g, q). */
const BOWL_R = '0,3 1,2 3,2 4,3 4,5 3,6 1,6 0,5';
const BOWL_L = '4,3 3,2 1,2 0,3 0,5 1,6 3,6 4,5';
const ARCH = '0,3 1,2 3,2 4,3 4,6';
const P = '0,6 0,0 3,0 4,1 4,2 3,3 0,3';

const SOURCE: Readonly<Record<string, string>> = {
  A: '0,6 2,0 4,6|0.7,4 3.3,4',
  B: '0,3 3,3 4,4 4,5 3,6 0,6 0,0 3,0 4,1 4,2 3,3',
  C: '4,1 3,0 1,0 0,1 0,5 1,6 3,6 4,5',
  D: '0,0 0,6 2.5,6 4,4.5 4,1.5 2.5,0 0,0',
  E: '4,0 0,0 0,6 4,6|0,3 3,3',
  F: '4,0 0,0 0,6|0,3 3,3',
  G: '4,1 3,0 1,0 0,1 0,5 1,6 3,6 4,5 4,3.5 2.5,3.5',
  H: '0,0 0,6|4,0 4,6|0,3 4,3',
  I: '1,0 3,0|2,0 2,6|1,6 3,6',
  J: '1,0 4,0|3,0 3,5 2,6 1,6 0,5',
  K: '0,0 0,6|4,0 0,4|1.3,2.7 4,6',
  L: '0,0 0,6 4,6',
  M: '0,6 0,0 2,3.5 4,0 4,6',
  N: '0,6 0,0 4,6 4,0',
  O,
  P,
  Q: `${O}|2.5,4.5 4,6.5`,
  R: `${P}|2,3 4,6`,
  S: '4,1 3,0 1,0 0,1 0,2 1,3 3,3 4,4 4,5 3,6 1,6 0,5',
  T: '0,0 4,0|2,0 2,6',
  U: '0,0 0,5 1,6 3,6 4,5 4,0',
  V: '0,0 2,6 4,0',
  W: '0,0 1,6 2,3 3,6 4,0',
  X: '0,0 4,6|4,0 0,6',
  Y: '0,0 2,3 4,0|2,3 2,6',
  Z: '0,0 4,0 0,6 4,6',
  a: `4,2 4,6|${BOWL_L}`,
  b: `0,0 0,6|${BOWL_R}`,
  c: '4,2.5 3.5,2 1,2 0,3 0,5 1,6 3.5,6 4,5.5',
  d: `4,0 4,6|${BOWL_L}`,
  e: '0,4 4,4 4,3 3,2 1,2 0,3 0,5 1,6 3.5,6',
  f: '3.5,0.5 3,0 2,0 1.5,0.5 1.5,6|0.5,2 3,2',
  g: `4,2 4,7 3,8 1,8|${BOWL_L}`,
  h: `0,0 0,6|${ARCH}`,
  i: '2,2 2,6|2,0.5 2,1',
  j: '2.5,2 2.5,7 1.5,8 0.5,8|2.5,0.5 2.5,1',
  k: '0,0 0,6|3.5,2 0,4.5|1.2,3.6 3.8,6',
  l: '1.5,0 1.5,5.5 2,6 2.5,6',
  m: '0,6 0,2|0,2.8 0.7,2 1.4,2 2,2.8 2,6|2,2.8 2.7,2 3.4,2 4,2.8 4,6',
  n: `0,2 0,6|${ARCH}`,
  o,
  p: `0,2 0,8|${BOWL_R}`,
  q: `4,2 4,8|${BOWL_L}`,
  r: '0,2 0,6|0,3.5 1.5,2 3.5,2',
  s: '4,2.5 3.5,2 0.5,2 0,2.5 0,3.5 0.5,4 3.5,4 4,4.5 4,5.5 3.5,6 0.5,6 0,5.5',
  t: '1.5,0.5 1.5,5.5 2,6 3,6|0.5,2 3,2',
  u: '0,2 0,5 1,6 3,6 4,5|4,2 4,6',
  v: '0,2 2,6 4,2',
  w: '0,2 1,6 2,3.5 3,6 4,2',
  x: '0,2 4,6|4,2 0,6',
  y: '0,2 2,6|4,2 2,6 1,8',
  z: '0,2 4,2 0,6 4,6',
  '0': `${O}|0.5,5 3.5,1`,
  '1': '1,1.5 2.5,0 2.5,6|1,6 4,6',
  '2': '0,1 1,0 3,0 4,1 4,2 0,6 4,6',
  '3': '0,0 4,0 2,2.5 3,2.5 4,3.5 4,5 3,6 1,6 0,5',
  '4': '3,6 3,0 0,4 4,4',
  '5': '4,0 0,0 0,2.5 3,2.5 4,3.5 4,5 3,6 0,6',
  '6': '3.5,0 1.5,0 0,2 0,5 1,6 3,6 4,5 4,4 3,3 0,3',
  '7': '0,0 4,0 1.5,6',
  '8': '1,0 0,1 0,2 1,3 3,3 4,2 4,1 3,0 1,0|1,3 0,4 0,5 1,6 3,6 4,5 4,4 3,3',
  '9': '4,3 1,3 0,2 0,1 1,0 3,0 4,1 4,4 2.5,6 0.5,6',
};

const parse = (glyph: string): Vec2[][] =>
  glyph.split('|').map((line) => line.split(' ').map((pt) => pt.split(',').map(Number) as unknown as Vec2));

const GLYPHS: ReadonlyMap<string, Vec2[][]> = new Map(
  Object.entries(SOURCE).map(([ch, g]) => [ch, parse(g)]),
);

/** Grid units from one letter's left edge to the next one's. */
export const ADVANCE = 5.5;
/** Grid units from the top of a capital to the baseline. */
export const CAP_HEIGHT = 6;

/** Whether the font draws character `ch` (others advance like a space). */
export const hasGlyph = (ch: string): boolean => GLYPHS.has(ch);

/** The polylines of `text` in pixels: its baseline starts at `origin`, capitals `capPx` tall. */
export function textStrokes(text: string, origin: Vec2, capPx: number): Vec2[][] {
  const s = capPx / CAP_HEIGHT;
  const out: Vec2[][] = [];
  [...text].forEach((ch, i) => {
    const x0 = origin[0] + i * ADVANCE * s;
    const y0 = origin[1] - CAP_HEIGHT * s;
    for (const line of GLYPHS.get(ch) ?? []) out.push(line.map(([x, y]): Vec2 => [x0 + x * s, y0 + y * s]));
  });
  return out;
}
