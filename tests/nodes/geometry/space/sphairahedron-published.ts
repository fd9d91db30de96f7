/**
 * The sphere radii of every published sphairahedron type as functions of the shape parameters, as
 * Nakamura–Ahara's renderer states them (github.com/soma-arc/SphairahedronExperiment, read for these
 * formulas only; docs/math-3d.md "The published types"). Order: the spheres of our construction —
 * cube S1 (height 0), S2 (zb), S3 (zc); pentahedral prism S_c, S_m; cake S1 (height 0), S2 (zb).
 * The construction derives them from the angle tables; the test checks the two agree.
 */
const R2 = Math.SQRT2;
const R3 = Math.sqrt(3);
const R6 = Math.sqrt(6);

type Radii = (zb: number, zc: number) => number[];

export const PUBLISHED_RADII: Readonly<Record<string, Radii>> = {
  'cube-a': (b, c) => [0.5 + (b * c) / 3, 0.5 + (b * b - b * c) / 3, 0.5 + (c * c - b * c) / 3],
  'cube-b': (b, c) => [
    (3 * R3 + 2 * R3 * b * c) / 9,
    (3 * b * b - 4 * b * c + 3) / 9,
    (3 * c * c - 2 * b * c + 6) / 9,
  ],
  'cube-c': (b, c) => [
    (b * b + 2 * b * c + 6) / (5 * R3),
    (3 * b * b - 4 * b * c + 3) / (5 * R3),
    (-b * b - 2 * b * c + 5 * c * c + 9) / 15,
  ],
  'cube-d': (b, c) => [
    (3 * b * b + c * c + 6 * b * c + 6) / 18,
    (15 * b * b - c * c - 6 * b * c + 12) / (18 * R3),
    (-3 * b * b + 5 * c * c - 6 * b * c + 12) / 18,
  ],
  'cube-e': (b, c) => [
    (c * c + 6 * b * c + 3) / (7 * R3),
    (7 * b * b - c * c - 6 * b * c + 4) / 14,
    (2 * c * c - 2 * b * c + 6) / 7,
  ],
  'cube-h': (b, c) => [
    (c * c + 2 * b * c + 2) / 6,
    (-c * c + 3 * b * b - 2 * b * c + 4) / (6 * R2),
    (c * c - b * c + 2) / 3,
  ],
  'cube-i': (b, c) => [(b * c) / 2, (b * b - b * c + 2) / (2 * R2), (c * c - b * c + 2) / (2 * R2)],
  'prism-a': (b) => [(b * b) / 3, 1],
  'prism-b': (b) => [(3 + 2 * b * b) / 6, R3 / 2],
  'prism-c': (b) => [(b * b - 3) / 3, R3],
  'prism-d': (b) => [(b * b) / R3, 1],
  'prism-e': (b) => [(b * b - 2) / 2, R2],
  'prism-f': (b) => [(b * b) / 2, 1],
  'cake-a': (b) => [(R6 * (2 + b * b)) / 8, (2 + b * b) / (4 * R2)],
  'cake-b': (b) => [(2 + b * b) / 4, (2 + b * b) / 4],
  'cake-c': (b) => [(2 + b * b) / (2 * R6), (2 + b * b) / (2 * R6)],
};
