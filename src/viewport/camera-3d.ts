/**
 * The 3D view's camera maths (pure): the pinhole camera's pixel ↔ ray mapping and the orbit,
 * zoom-about-the-cursor and pan moves of the pointer controls (docs/math-3d.md "The 3D view:
 * camera moves and overlay projection"). Pixels here are CSS pixels of the pane, x right and y
 * DOWN from its top-left corner, the way pointer events and the SVG overlay count them.
 */
import type { Camera3d } from '../../nodes/core/scene-3d.ts';
import { add3, dot3, len3, scale3, sub3, type Vec3 } from '../../nodes/geometry/space/vec3.ts';
import { type CameraBasis, cameraBasis, rayDirection } from '../../shader-gen/space/camera-3d.ts';

export interface PaneSize {
  readonly width: number;
  readonly height: number;
}

/** Orbiting stops this far short of the poles, so "up" on screen never flips. */
export const MAX_ELEVATION = (85 * Math.PI) / 180;
/** Closest and farthest the camera may come to its target (world units). */
export const MIN_DISTANCE = 1e-3;
export const MAX_DISTANCE = 1e4;
/** Points nearer than this in front of the camera are not projected (behind the near plane). */
export const NEAR = 1e-4;

/**
 * The camera's frame — forward f, right r, up u (docs/math-3d.md "The 3D view: camera moves and
 * overlay projection") — is the tracer's own (shader-gen/space/camera-3d.ts), so the overlay,
 * the drags and the picture agree to the last bit of the formula.
 */
export { type CameraBasis, cameraBasis };

/** tan of half the vertical field of view: the picture's half-height at distance 1. */
export const halfHeightAt1 = (camera: Camera3d): number => Math.tan((camera.fovDeg * Math.PI) / 360);

/**
 * Unit ray direction through pane pixel (x, y) (y down): with t = tan(fov/2),
 * d ∝ f + ((2x − W)/H)·t·r + ((H − 2y)/H)·t·u — the tracer's ray through (x, H − y).
 */
export function rayThrough(camera: Camera3d, pane: PaneSize, x: number, y: number): Vec3 {
  return rayDirection(cameraBasis(camera), pane.width, pane.height, x, pane.height - y);
}

export interface Projected {
  readonly x: number;
  readonly y: number;
  /** Distance along the view direction ((p − position)·f). */
  readonly depth: number;
}

/**
 * Pane pixel of world point p, the inverse of rayThrough: with q = p − position and
 * z = q·f, x = W/2 + (q·r / z)·H/(2t), y = H/2 − (q·u / z)·H/(2t). Null behind the near plane.
 */
export function project(camera: Camera3d, pane: PaneSize, p: Vec3): Projected | null {
  return projectWith(cameraBasis(camera), camera, pane, p);
}

/** project() with the basis computed once (the overlay projects many points per frame). */
export function projectWith(basis: CameraBasis, camera: Camera3d, pane: PaneSize, p: Vec3): Projected | null {
  const q = sub3(p, camera.position);
  const depth = dot3(q, basis.forward);
  if (!(depth > NEAR)) return null;
  const k = pane.height / (2 * halfHeightAt1(camera) * depth);
  return {
    x: pane.width / 2 + dot3(q, basis.right) * k,
    y: pane.height / 2 - dot3(q, basis.up) * k,
    depth,
  };
}

/**
 * The point under pixel (x, y) in the plane through `through` parallel to the screen (normal f):
 * position + s·d with s = ((through − position)·f)/(d·f). Null when that plane is behind the camera.
 */
export function pointOnScreenPlane(
  camera: Camera3d,
  pane: PaneSize,
  through: Vec3,
  x: number,
  y: number,
): Vec3 | null {
  const { forward } = cameraBasis(camera);
  const d = rayThrough(camera, pane, x, y);
  const s = dot3(sub3(through, camera.position), forward) / dot3(d, forward);
  if (!(s > NEAR) || !Number.isFinite(s)) return null;
  return add3(camera.position, scale3(d, s));
}

/**
 * Orbit about the target: the offset position − target in spherical coordinates
 * (distance, azimuth θ, elevation φ) = ρ·(cos φ cos θ, cos φ sin θ, sin φ), turned by
 * (dAzimuth, dElevation) radians with φ kept within ±MAX_ELEVATION (z stays up).
 */
export function orbit(camera: Camera3d, dAzimuth: number, dElevation: number): Camera3d {
  const o = sub3(camera.position, camera.target);
  const rho = len3(o);
  if (!(rho > 0)) return camera;
  const azimuth = Math.atan2(o[1], o[0]) + dAzimuth;
  const raw = Math.asin(Math.max(-1, Math.min(1, o[2] / rho))) + dElevation;
  const elevation = Math.max(-MAX_ELEVATION, Math.min(MAX_ELEVATION, raw));
  const c = Math.cos(elevation);
  const offset: Vec3 = [rho * c * Math.cos(azimuth), rho * c * Math.sin(azimuth), rho * Math.sin(elevation)];
  return { ...camera, position: add3(camera.target, offset) };
}

/**
 * Zoom about pixel (x, y) by `factor` (< 1: closer): the homothety with centre A, the point under
 * the pixel in the plane through the target parallel to the screen, applied to position and target
 * (p' = A + k(p − A)). The orientation is unchanged and A is fixed, so A — and the whole ray under
 * the cursor — stays under the cursor. k is limited so the distance stays in [MIN, MAX]_DISTANCE.
 */
export function zoomAbout(camera: Camera3d, pane: PaneSize, x: number, y: number, factor: number): Camera3d {
  const anchor = pointOnScreenPlane(camera, pane, camera.target, x, y);
  const distance = len3(sub3(camera.target, camera.position));
  if (!anchor || !(distance > 0) || !(factor > 0)) return camera;
  const k = Math.min(MAX_DISTANCE / distance, Math.max(MIN_DISTANCE / distance, factor));
  const about = (p: Vec3) => add3(anchor, scale3(sub3(p, anchor), k));
  return { ...camera, position: about(camera.position), target: about(camera.target) };
}

/**
 * Pan by (dx, dy) pane pixels: position and target move together, parallel to the screen, so that
 * the points in the plane through the target follow the pointer: a pixel there spans
 * 2·t·depth/H world units, and the move is −(dx·r − dy·u) times that.
 */
export function pan(camera: Camera3d, pane: PaneSize, dx: number, dy: number): Camera3d {
  const { forward, right, up } = cameraBasis(camera);
  const depth = dot3(sub3(camera.target, camera.position), forward);
  const perPixel = (2 * halfHeightAt1(camera) * depth) / pane.height;
  const move = scale3(sub3(scale3(up, dy), scale3(right, dx)), perPixel);
  return { ...camera, position: add3(camera.position, move), target: add3(camera.target, move) };
}
