/**
 * Where the overlay's labels go so that no two overlap: each label has candidate boxes around its
 * anchor (eight compass positions around a point; a position just outside the rim at every 45°
 * for a circle), and labels are placed greedily, highest priority first, each in its first
 * candidate that lies inside the view and clears every label already placed. Candidates that also
 * keep off the drawn points and handles are preferred, if need be a little farther out. A label
 * with no free candidate is left out: a missing label is better than two unreadable ones. Pure:
 * sizes in CSS pixels, no DOM.
 */

export type Vec2 = readonly [number, number];

/** A screen rectangle: top-left corner and size. */
export interface Box {
  readonly x: number;
  readonly y: number;
  readonly width: number;
  readonly height: number;
}

/** One place a label may go: an anchor on its shape and the compass direction it sits in from it. */
export interface Candidate {
  readonly anchor: Vec2;
  /** Each of -1, 0 or 1 (screen axes, y down): (1, -1) puts the label up-right of the anchor. */
  readonly dir: Vec2;
}

export interface LabelRequest {
  readonly id: string;
  readonly width: number;
  readonly height: number;
  /** Higher is placed first (and so keeps its preferred position). */
  readonly priority: number;
  /** Distance from the anchor to the label's box (clears a point's dot and handle). */
  readonly gap: number;
  readonly candidates: readonly Candidate[];
}

export interface LabelView {
  readonly width: number;
  readonly height: number;
}

/** Labels keep this far from each other and from the view's edges. */
export const LABEL_MARGIN = 3;
/** When every near candidate covers a drawn point, the same candidates this much farther out. */
export const FAR_RING_PX = 14;

/** The eight compass directions in order of preference: up-right first (the usual place). */
const COMPASS: readonly Vec2[] = [
  [1, -1],
  [1, 1],
  [-1, -1],
  [-1, 1],
  [1, 0],
  [-1, 0],
  [0, -1],
  [0, 1],
];

/** A point's candidates: the eight positions around it. */
export function pointCandidates(at: Vec2): Candidate[] {
  return COMPASS.map((dir) => ({ anchor: at, dir }));
}

/**
 * A circle's candidates: just outside the rim at 45°, 135°, 315°, 225°, 90°, 270°, 0° and 180°
 * (screen angles, counter-clockwise as seen), each pointing away from the centre. The rim point
 * at screen angle θ is c + r (cos θ, −sin θ).
 */
export function circleCandidates(c: Vec2, r: number): Candidate[] {
  return COMPASS.map((dir) => {
    const len = Math.hypot(dir[0], dir[1]);
    return { anchor: [c[0] + (r * dir[0]) / len, c[1] + (r * dir[1]) / len] as Vec2, dir };
  });
}

/** The label's box for a candidate, `gap` pixels from its anchor. */
export function candidateBox(c: Candidate, width: number, height: number, gap: number): Box {
  const [ax, ay] = c.anchor;
  const [sx, sy] = c.dir;
  const x = sx > 0 ? ax + gap : sx < 0 ? ax - gap - width : ax - width / 2;
  const y = sy < 0 ? ay - gap - height : sy > 0 ? ay + gap : ay - height / 2;
  return { x, y, width, height };
}

/** Whether two boxes overlap once each is grown by `margin` on every side. */
export function boxesIntersect(a: Box, b: Box, margin = 0): boolean {
  return (
    a.x < b.x + b.width + margin &&
    b.x < a.x + a.width + margin &&
    a.y < b.y + b.height + margin &&
    b.y < a.y + a.height + margin
  );
}

const insideView = (b: Box, v: LabelView) =>
  b.x >= LABEL_MARGIN &&
  b.y >= LABEL_MARGIN &&
  b.x + b.width <= v.width - LABEL_MARGIN &&
  b.y + b.height <= v.height - LABEL_MARGIN;

const anchorInView = (a: Vec2, v: LabelView) => a[0] >= 0 && a[1] >= 0 && a[0] <= v.width && a[1] <= v.height;

/**
 * Places every label it can; returns each placed label's box by id. `obstacles` (the drawn points)
 * are avoided when some candidate allows it; other labels and the view's edges always are.
 */
export function placeLabels(
  requests: readonly LabelRequest[],
  view: LabelView,
  obstacles: readonly Box[] = [],
): Map<string, Box> {
  const order = requests.map((r, i) => ({ r, i })).sort((a, b) => b.r.priority - a.r.priority || a.i - b.i);
  const placed = new Map<string, Box>();
  for (const { r } of order) {
    const free = (gap: number) =>
      r.candidates
        .filter((c) => anchorInView(c.anchor, view))
        .map((c) => candidateBox(c, r.width, r.height, gap))
        .filter(
          (b) => insideView(b, view) && ![...placed.values()].some((p) => boxesIntersect(b, p, LABEL_MARGIN)),
        );
    const near = free(r.gap);
    const clear = (boxes: Box[]) => boxes.find((b) => !obstacles.some((o) => boxesIntersect(b, o)));
    const box = clear(near) ?? clear(free(r.gap + FAR_RING_PX)) ?? near[0];
    if (box) placed.set(r.id, box);
  }
  return placed;
}
