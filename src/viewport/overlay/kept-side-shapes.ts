/**
 * Where the overlay shows which side each mirror keeps (pure, CSS pixels). A mirror is drawn like
 * the optics symbol: a hatched band along its back — the discarded side, whose points the IIS maps
 * across — so the tile (the region every mirror keeps) is the side without hatching. The hovered
 * mirror also shades its whole discarded side softly.
 */
import type { SceneElement } from '../../../nodes/core/scene.ts';
import type { Vec2 } from '../../../nodes/core/values.ts';
import { depthInSide } from '../../../nodes/geometry/kept-region.ts';
import { keptSideOf } from '../../../nodes/graph/mirror-check.ts';
import { clipLineToRect, pxPerWorld, type Screen, toCss, toWorld } from './screen.ts';

/** Width of the hatched band on a mirror's back, in CSS pixels. */
export const BAND_PX = 9;

export type KeptSideShape =
  | {
      readonly kind: 'line';
      readonly nodeId: string;
      /** The band: the visible segment and its copy BAND_PX towards the discarded side. */
      readonly band: readonly Vec2[];
      /** The discarded half-plane clipped to the pane. */
      readonly discarded: readonly Vec2[];
    }
  | {
      readonly kind: 'circle';
      readonly nodeId: string;
      readonly c: Vec2;
      readonly r: number;
      /** A circle mirror with `flip`: its back is the outside. */
      readonly keepInside: boolean;
    };

/** The pane's corners, clockwise from the top-left, cut to where `inside` ≥ 0 (one clip plane). */
function clipPane(s: Screen, inside: (p: Vec2) => number): Vec2[] {
  const corners: Vec2[] = [
    [0, 0],
    [s.width, 0],
    [s.width, s.height],
    [0, s.height],
  ];
  const out: Vec2[] = [];
  for (let i = 0; i < 4; i++) {
    const a = corners[i];
    const b = corners[(i + 1) % 4];
    const fa = inside(a);
    const fb = inside(b);
    if (fa >= 0) out.push(a);
    if (fa >= 0 !== fb >= 0) {
      const t = fa / (fa - fb);
      out.push([a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1])]);
    }
  }
  return out;
}

export function keptSideShapes(elements: readonly SceneElement[], s: Screen): KeptSideShape[] {
  const shapes: KeptSideShape[] = [];
  const k = pxPerWorld(s);
  for (const e of elements) {
    const side = keptSideOf(e);
    if (!side) continue;
    if (side.kind === 'disk') {
      const c = toCss(s, side.c);
      shapes.push({ kind: 'circle', nodeId: e.nodeId, c, r: side.r * k, keepInside: side.keepInside });
      continue;
    }
    const a = toCss(s, side.q);
    const b = toCss(s, [side.q[0] + side.n[1], side.q[1] - side.n[0]]);
    const seg = clipLineToRect(a, b, s.width, s.height, BAND_PX);
    if (!seg) continue;
    // The discarded side's direction on screen (y is down, so map a world step rather than guess).
    const back = toCss(s, [side.q[0] - side.n[0] / k, side.q[1] - side.n[1] / k]);
    const off: Vec2 = [(back[0] - a[0]) * BAND_PX, (back[1] - a[1]) * BAND_PX];
    shapes.push({
      kind: 'line',
      nodeId: e.nodeId,
      band: [
        seg[0],
        seg[1],
        [seg[1][0] + off[0], seg[1][1] + off[1]],
        [seg[0][0] + off[0], seg[0][1] + off[1]],
      ],
      discarded: clipPane(s, (p) => -depthInSide(side, toWorld(s, p))),
    });
  }
  return shapes;
}
