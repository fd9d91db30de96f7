/**
 * The parameter-space picture's data (paper Fig. 30): a sphairahedron type's classes on a grid of
 * the (zb, zc) plane (docs/math-3d.md "The parameter space: bridges and tunnels").
 */
import { infiniteSphairahedron } from './sphairahedron.ts';
import { SPACE_CLASSES, spaceClass } from './sphairahedron-space.ts';
import type { SphairahedronType } from './sphairahedron-types.ts';

/** A square window of the (zb, zc) plane: its centre and half its side. */
export interface SpaceWindow {
  readonly center: readonly [number, number];
  readonly half: number;
}

/**
 * The classes on an n × rows grid of cell centres over the window (row 0 at the top, zc largest),
 * as indices into SPACE_CLASSES. Types with zb only (pentahedral prism, cake) take rows = 1: the
 * zb axis. Each cell builds the shape (docs/math-3d.md "The parameter space: bridges and tunnels").
 */
export function spaceGrid(type: SphairahedronType, win: SpaceWindow, n: number, rows = n): Uint8Array {
  const out = new Uint8Array(n * rows);
  const cell = (2 * win.half) / n;
  for (let j = 0; j < rows; j++) {
    const zc = rows === 1 ? 0 : win.center[1] + win.half - (j + 0.5) * cell;
    for (let i = 0; i < n; i++) {
      const zb = win.center[0] - win.half + (i + 0.5) * cell;
      out[j * n + i] = SPACE_CLASSES.indexOf(spaceClass(infiniteSphairahedron(type, zb, zc)));
    }
  }
  return out;
}
