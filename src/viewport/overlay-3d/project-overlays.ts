/**
 * The 3D overlay on screen (pure): each Overlay3dItem as SVG-ready pane pixels through the view's
 * camera (camera-3d.ts) — a point as a dot, a sphere as its outline (the exact silhouette ellipse,
 * sampled), a plane as a small square patch with its normal, a box as its twelve edges — and each
 * Handle3dItem as a dot. Anything behind the camera is left out or clipped at the near plane
 * (docs/math-3d.md "The 3D view: camera moves and overlay projection").
 */
import type { Camera3d, Handle3dItem, Overlay3dItem, Plane, Sphere } from '../../../nodes/core/scene-3d.ts';
import {
  add3,
  cross3,
  dot3,
  normalize3,
  scale3,
  sub3,
  type Vec3,
} from '../../../nodes/geometry/space/vec3.ts';
import {
  type CameraBasis,
  cameraBasis,
  halfHeightAt1,
  NEAR,
  type PaneSize,
  projectWith,
} from '../camera-3d.ts';

export type ScreenPoint = readonly [number, number];

export interface Screen3dItem {
  readonly nodeId: string;
  readonly color: string;
  readonly label?: string;
  /** A dot (points) or null. */
  readonly dot: ScreenPoint | null;
  /** Polylines in pane pixels (closed ones repeat their first point). */
  readonly lines: readonly (readonly ScreenPoint[])[];
}

export interface Screen3dHandle extends Handle3dItem {
  readonly x: number;
  readonly y: number;
  readonly depth: number;
}

/** Points on a sphere's outline: enough for a smooth ellipse at any size on screen. */
const OUTLINE_SEGMENTS = 64;
/** Half the side of a plane's patch, as a fraction of the visible half-height at its depth. */
const PLANE_PATCH = 0.25;

interface Projector {
  readonly camera: Camera3d;
  readonly basis: CameraBasis;
  readonly pane: PaneSize;
}

const at = (pr: Projector, p: Vec3): ScreenPoint | null => {
  const q = projectWith(pr.basis, pr.camera, pr.pane, p);
  return q ? [q.x, q.y] : null;
};

const depthOf = (pr: Projector, p: Vec3) => dot3(sub3(p, pr.camera.position), pr.basis.forward);

/** The segment a→b cut to the part in front of the near plane (depth ≥ NEAR·2), projected; null when none is. */
function segment(pr: Projector, a: Vec3, b: Vec3): ScreenPoint[] | null {
  const near = 2 * NEAR;
  const da = depthOf(pr, a);
  const db = depthOf(pr, b);
  if (da < near && db < near) return null;
  const cut = (from: Vec3, to: Vec3, df: number, dt: number) =>
    add3(from, scale3(sub3(to, from), (near - df) / (dt - df)));
  const a2 = da < near ? cut(a, b, da, db) : a;
  const b2 = db < near ? cut(b, a, db, da) : b;
  const pa = at(pr, a2);
  const pb = at(pr, b2);
  return pa && pb ? [pa, pb] : null;
}

/** A closed loop of world points, projected; null when any point is behind the camera. */
function loop(pr: Projector, points: readonly Vec3[]): ScreenPoint[] | null {
  const out: ScreenPoint[] = [];
  for (const p of points) {
    const s = at(pr, p);
    if (!s) return null;
    out.push(s);
  }
  out.push(out[0]);
  return out;
}

/** Two unit vectors perpendicular to n and to each other. */
function perpendiculars(n: Vec3): [Vec3, Vec3] {
  const helper: Vec3 = Math.abs(n[2]) < 0.9 ? [0, 0, 1] : [1, 0, 0];
  const u = normalize3(cross3(n, helper));
  return [u, cross3(n, u)];
}

/**
 * A sphere's silhouette from the eye o: the circle where the tangent cone touches it. With
 * v = c − o, D = |v|: its centre is o + v(1 − R²/D²), its radius R·√(D² − R²)/D, in the plane ⟂ v.
 * Projected, it is the outline ellipse. None when the eye is inside the sphere.
 */
function sphereOutline(pr: Projector, s: Sphere): ScreenPoint[] | null {
  const v = sub3(s.center, pr.camera.position);
  const d2 = dot3(v, v);
  const r2 = s.radius * s.radius;
  if (!(d2 > r2)) return null;
  const centre = add3(pr.camera.position, scale3(v, 1 - r2 / d2));
  const radius = (s.radius * Math.sqrt(d2 - r2)) / Math.sqrt(d2);
  const [u, w] = perpendiculars(normalize3(v));
  const points: Vec3[] = [];
  for (let i = 0; i < OUTLINE_SEGMENTS; i++) {
    const a = (2 * Math.PI * i) / OUTLINE_SEGMENTS;
    points.push(add3(centre, add3(scale3(u, radius * Math.cos(a)), scale3(w, radius * Math.sin(a)))));
  }
  return loop(pr, points);
}

/** A square patch of the plane around its point (sized to the view at that depth) and its normal. */
function planePatch(pr: Projector, plane: Plane): ScreenPoint[][] {
  const depth = Math.max(depthOf(pr, plane.point), NEAR);
  const half = PLANE_PATCH * halfHeightAt1(pr.camera) * depth;
  const [u, w] = perpendiculars(normalize3(plane.normal));
  const corner = (a: number, b: number) => add3(plane.point, add3(scale3(u, a * half), scale3(w, b * half)));
  const square = loop(pr, [corner(-1, -1), corner(1, -1), corner(1, 1), corner(-1, 1)]);
  const normal = segment(pr, plane.point, add3(plane.point, scale3(normalize3(plane.normal), half)));
  return [square, normal].filter((l): l is ScreenPoint[] => l !== null);
}

/** The twelve edges of an axis-aligned box: pairs of corners differing in exactly one coordinate. */
function boxEdges(pr: Projector, center: Vec3, half: Vec3): ScreenPoint[][] {
  const corner = (i: number): Vec3 => [
    center[0] + (i & 1 ? half[0] : -half[0]),
    center[1] + (i & 2 ? half[1] : -half[1]),
    center[2] + (i & 4 ? half[2] : -half[2]),
  ];
  const lines: ScreenPoint[][] = [];
  for (let i = 0; i < 8; i++) {
    for (const bit of [1, 2, 4]) {
      if (i & bit) continue;
      const s = segment(pr, corner(i), corner(i | bit));
      if (s) lines.push(s);
    }
  }
  return lines;
}

function placeOne(pr: Projector, item: Overlay3dItem): Screen3dItem {
  const base = { nodeId: item.nodeId, color: item.color, label: item.label };
  const s = item.shape;
  switch (s.shape) {
    case 'point':
      return { ...base, dot: at(pr, s.at), lines: [] };
    case 'sphere': {
      const outline = sphereOutline(pr, s.sphere);
      return { ...base, dot: null, lines: outline ? [outline] : [] };
    }
    case 'plane':
      return { ...base, dot: null, lines: planePatch(pr, s.plane) };
    case 'box':
      return { ...base, dot: null, lines: boxEdges(pr, s.center, s.halfSize) };
  }
}

const projector = (camera: Camera3d, pane: PaneSize): Projector => ({
  camera,
  basis: cameraBasis(camera),
  pane,
});

/** Every overlay item on screen (items wholly behind the camera come back with nothing to draw). */
export function placeOverlays3d(
  items: readonly Overlay3dItem[],
  camera: Camera3d,
  pane: PaneSize,
): Screen3dItem[] {
  const pr = projector(camera, pane);
  return items.map((item) => placeOne(pr, item));
}

/** Handles in front of the camera with their pane pixels, nearest last (drawn on top, hit first). */
export function placeHandles3d(
  handles: readonly Handle3dItem[],
  camera: Camera3d,
  pane: PaneSize,
): Screen3dHandle[] {
  const pr = projector(camera, pane);
  const out: Screen3dHandle[] = [];
  for (const h of handles) {
    const q = projectWith(pr.basis, camera, pane, h.at);
    if (q && Number.isFinite(q.x) && Number.isFinite(q.y)) out.push({ ...h, x: q.x, y: q.y, depth: q.depth });
  }
  return out.sort((a, b) => b.depth - a.depth);
}

/** SVG path data of a polyline. */
export const pathData = (line: readonly ScreenPoint[]): string =>
  line.map(([x, y], i) => `${i === 0 ? 'M' : 'L'}${x.toFixed(1)} ${y.toFixed(1)}`).join('');

/** Pixel distance from p to the segment a–b: |p − (a + t(b − a))| with t the clamped projection. */
function segmentDistance(p: ScreenPoint, a: ScreenPoint, b: ScreenPoint): number {
  const dx = b[0] - a[0];
  const dy = b[1] - a[1];
  const l2 = dx * dx + dy * dy;
  const t = l2 > 0 ? Math.max(0, Math.min(1, ((p[0] - a[0]) * dx + (p[1] - a[1]) * dy) / l2)) : 0;
  return Math.hypot(p[0] - (a[0] + t * dx), p[1] - (a[1] + t * dy));
}

/** The node of the drawn item nearest to p within `tolerance` pixels (dots and lines), or null. */
export function itemNear(items: readonly Screen3dItem[], p: ScreenPoint, tolerance: number): string | null {
  let best: string | null = null;
  let bestDistance = tolerance;
  for (const item of items) {
    let d = item.dot ? Math.hypot(p[0] - item.dot[0], p[1] - item.dot[1]) : Infinity;
    for (const line of item.lines)
      for (let i = 1; i < line.length; i++) d = Math.min(d, segmentDistance(p, line[i - 1], line[i]));
    if (d <= bestDistance) {
      best = item.nodeId;
      bestDistance = d;
    }
  }
  return best;
}
