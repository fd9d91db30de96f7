/**
 * Sizes and tolerances of the render overlay, in CSS pixels (one home for each; the hit tests,
 * the snapping and the drawing all read them from here).
 */
export const OVERLAY_PX = {
  /** A pointer this close to a handle's centre grabs it (the nearest handle wins). */
  handleHit: 8,
  /** A press and release this close together (no pan to speak of) is a click: it may place a handle. */
  clickSlop: 3,
  /** A pointer this close to a point, line or circle hovers its node. */
  geometryHit: 5,
  /** A dragged rim this close to tangency with another circle snaps to it (Shift held). */
  tangentSnap: 12,
  /** Grid cells are the smallest "nice" step (1, 2 or 5 × 10^k world units) at least this wide. */
  gridMinCell: 20,
  /** Radius of a drawn handle, and of a hovered one. */
  handleRadius: 5,
  handleRadiusHover: 7,
  /** Radius of a drawn construction point. */
  pointRadius: 3.5,
  /** Width of a construction stroke, of a hovered one, and of the dark outline added around both. */
  stroke: 2,
  strokeHover: 3.5,
  outline: 2,
  /** Lines are extended to the view's edges plus this margin (so their ends never show). */
  lineMargin: 16,
  /** Labels sit this far from their point or circle. */
  labelOffset: 8,
  /** Font size of node labels. */
  labelFont: 13,
} as const;

/** Angle snapping steps in multiples of π / ANGLE_SNAP_DIVISIONS (15°). */
export const ANGLE_SNAP_DIVISIONS = 12;

/** Shift-dragging a line end also snaps its angle with every other drawn line to π/n, n ≤ this. */
export const MIRROR_SNAP_MAX_N = 12;
