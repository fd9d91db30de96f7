/** 3-D vector helpers on Vec3 = [x, y, z] (readonly tuples, mirroring Vec2 in ../vec.ts). */
export type Vec3 = readonly [number, number, number];

export const vec3 = (x: number, y: number, z: number): Vec3 => [x, y, z];
export const add3 = (a: Vec3, b: Vec3): Vec3 => [a[0] + b[0], a[1] + b[1], a[2] + b[2]];
export const sub3 = (a: Vec3, b: Vec3): Vec3 => [a[0] - b[0], a[1] - b[1], a[2] - b[2]];
export const scale3 = (a: Vec3, k: number): Vec3 => [a[0] * k, a[1] * k, a[2] * k];
export const dot3 = (a: Vec3, b: Vec3): number => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
/** a × b = (a_y b_z − a_z b_y, a_z b_x − a_x b_z, a_x b_y − a_y b_x). */
export const cross3 = (a: Vec3, b: Vec3): Vec3 => [
  a[1] * b[2] - a[2] * b[1],
  a[2] * b[0] - a[0] * b[2],
  a[0] * b[1] - a[1] * b[0],
];
export const len2v3 = (a: Vec3): number => dot3(a, a);
export const len3 = (a: Vec3): number => Math.hypot(a[0], a[1], a[2]);
export const dist3 = (a: Vec3, b: Vec3): number => len3(sub3(a, b));
/** Unit vector a/|a|; the zero vector stays zero. */
export const normalize3 = (a: Vec3): Vec3 => {
  const l = len3(a);
  return l > 0 ? scale3(a, 1 / l) : [0, 0, 0];
};
