/** 2-D vector helpers on Vec2 = [x, y] (pure, allocation-light). */
import type { Vec2 } from '../core/values.ts';

export const vec = (x: number, y: number): Vec2 => [x, y];
export const add = (a: Vec2, b: Vec2): Vec2 => [a[0] + b[0], a[1] + b[1]];
export const sub = (a: Vec2, b: Vec2): Vec2 => [a[0] - b[0], a[1] - b[1]];
export const scale = (a: Vec2, k: number): Vec2 => [a[0] * k, a[1] * k];
export const dot = (a: Vec2, b: Vec2): number => a[0] * b[0] + a[1] * b[1];
/** z-component of the 3-D cross product: a_x b_y − a_y b_x. */
export const cross = (a: Vec2, b: Vec2): number => a[0] * b[1] - a[1] * b[0];
export const len2 = (a: Vec2): number => a[0] * a[0] + a[1] * a[1];
export const len = (a: Vec2): number => Math.hypot(a[0], a[1]);
export const dist = (a: Vec2, b: Vec2): number => Math.hypot(a[0] - b[0], a[1] - b[1]);
export const dist2 = (a: Vec2, b: Vec2): number => len2(sub(a, b));
/** Unit vector a/|a|; [0, 0] stays [0, 0]. */
export const normalize = (a: Vec2): Vec2 => {
  const l = len(a);
  return l > 0 ? [a[0] / l, a[1] / l] : [0, 0];
};
/** Rotation by +90°: (x, y) ↦ (−y, x). */
export const perp = (a: Vec2): Vec2 => [-a[1], a[0]];
/** Rotation by angle t (radians, counter-clockwise). */
export const rotate = (a: Vec2, t: number): Vec2 => {
  const c = Math.cos(t);
  const s = Math.sin(t);
  return [c * a[0] - s * a[1], s * a[0] + c * a[1]];
};
export const lerp = (a: Vec2, b: Vec2, t: number): Vec2 => [
  a[0] + (b[0] - a[0]) * t,
  a[1] + (b[1] - a[1]) * t,
];
export const nearlyEqual = (a: Vec2, b: Vec2, eps = 1e-9): boolean => dist(a, b) <= eps;
