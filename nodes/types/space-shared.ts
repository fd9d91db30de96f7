/**
 * Helpers shared by the 3D node types (docs/math-3d.md): port specs, the checks every sphere and
 * plane input gets, the handles of a sphere, and how a seed or a point sits in the IIS regions.
 */
import type { InputSpec } from '../core/define-node.ts';
import type { NodeElement3d, Plane, Sphere, Vec3 } from '../core/scene-3d.ts';
import { stepElement3d } from '../geometry/space/iis-3d.ts';
import { add3, dist3, len3, sub3 } from '../geometry/space/vec3.ts';
import { fmt } from './shared.ts';

export const point3Input = (label: string, x: number, y: number, z: number, doc?: string) =>
  ({ type: 'point3', label, default: [x, y, z], ...(doc ? { doc } : {}) }) as const satisfies InputSpec;
export const sphereInput = (label: string, center: Vec3, radius: number) =>
  ({ type: 'sphere', label, default: { center, radius } }) as const satisfies InputSpec;
export const planeInput = (label: string, point: Vec3, normal: Vec3) =>
  ({ type: 'plane', label, default: { point, normal } }) as const satisfies InputSpec;
export const element3Input = (label: string) =>
  ({ type: 'element3', label, optional: true }) as const satisfies InputSpec;

/** Formats a point of space for read-outs: "(1, 0, 2.5)". */
export const fmt3 = (p: Vec3): string => `(${p.map(fmt).join(', ')})`;

/** Why a sphere cannot be used (radius ≤ 0 or not finite), or null. */
export function sphereProblem(s: Sphere, name = 'the sphere'): string | null {
  if (!Number.isFinite(s.radius) || !s.center.every(Number.isFinite))
    return `${name} is not finite (NaN or ∞)`;
  return s.radius > 0 ? null : `${name}'s radius must be positive, got ${fmt(s.radius)}`;
}

/** Why a plane cannot be used (zero normal), or null. Inline planes are normalised on reading. */
export function planeProblem(p: Plane, name = 'the plane'): string | null {
  return len3(p.normal) > 0 ? null : `${name}'s normal is zero: it has no direction`;
}

/** A sphere's handles: its centre, and a point on it (+x from the centre) for the radius. */
export const sphereHandles = (s: Sphere) => [
  { handle: 'center', at: s.center },
  { handle: 'radius', at: add3(s.center, [s.radius, 0, 0]) },
];

/** Smallest radius a radius drag may leave (the node would fail at 0). */
export const MIN_RADIUS = 1e-6;

/** A radius handle dragged to `to`: the radius is its distance from the centre. */
export const radiusTo = (center: Vec3, to: Vec3): number => Math.max(MIN_RADIUS, dist3(center, to));

/**
 * Handles of a sphere-valued input `key` of an element node: `key.center` and `key.radius`. When
 * the input is wired, the drag follows the upstream node's own centre / radius handles
 * (nodes/graph/drag-patches-3d.ts).
 */
export const sphereInputHandles = (key: string, s: Sphere) =>
  sphereHandles({ center: s.center, radius: Math.max(0, s.radius) }).map((h) => ({
    handle: `${key}.${h.handle}`,
    at: h.at,
  }));

/** A drag of `key.center` / `key.radius` → the input's new value (document form). */
export function dragSphereInput(handle: string, to: Vec3, key: string, s: Sphere): Record<string, unknown> {
  if (handle === `${key}.center`) return { [key]: { center: [...to], radius: s.radius } };
  if (handle === `${key}.radius`) return { [key]: { center: [...s.center], radius: radiusTo(s.center, to) } };
  return {};
}

/** Handles of a plane-valued input `key`: `key.point` and `key.normal` (the tip of the unit normal). */
export const planeInputHandles = (key: string, p: Plane) => [
  { handle: `${key}.point`, at: p.point },
  { handle: `${key}.normal`, at: add3(p.point, p.normal) },
];

/** A drag of `key.point` / `key.normal` → the input's new value (document form). */
export function dragPlaneInput(handle: string, to: Vec3, key: string, p: Plane): Record<string, unknown> {
  if (handle === `${key}.point`) return { [key]: { point: [...to], normal: [...p.normal] } };
  if (handle === `${key}.normal`) {
    const n = [to[0] - p.point[0], to[1] - p.point[1], to[2] - p.point[2]];
    return n.some((v) => v !== 0) ? { [key]: { point: [...p.point], normal: n } } : {};
  }
  return {};
}

/** Why an axis-aligned box cannot be used (a half size ≤ 0 or not finite), or null. */
export function boxProblem(halfSize: Vec3): string | null {
  return halfSize.every((h) => h > 0 && Number.isFinite(h))
    ? null
    : `the box needs a positive half size along x, y and z, got ${fmt3(halfSize)}`;
}

/** Handles of an axis-aligned box: its centre and its +x+y+z corner (the half size). */
export const boxHandles = (center: Vec3, halfSize: Vec3) => [
  { handle: 'center', at: center },
  { handle: 'corner', at: add3(center, halfSize) },
];

/** A box drag → the new centre, or the half size from the corner's offset per axis (kept positive). */
export const dragBox = (handle: string, to: Vec3, center: Vec3): Record<string, unknown> =>
  handle === 'center'
    ? { center: [...to] }
    : { halfSize: sub3(to, center).map((v) => Math.max(MIN_RADIUS, Math.abs(v))) };

/** The element whose region (the part of space it moves) holds x, or undefined. */
export const elementHolding = (elements: readonly NodeElement3d[], x: Vec3): NodeElement3d | undefined =>
  elements.find((e) => stepElement3d(e, x) !== null);
