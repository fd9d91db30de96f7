/**
 * The sphairahedra with a vertex at infinity that Nakamura–Ahara list — cube A–E, H, I, pentahedral
 * prism A–F, cake A–C: which dihedral angle π/n sits on which edge (docs/math-3d.md "Sphairahedra
 * (paper §5.3)", "The published types"). Only angles are listed here; the shapes are built by
 * sphairahedron.ts and sphairahedron-cake.ts. The angles were read off the published renderer's
 * sphere formulas (facts, see the docs); the tests measure them on the built shapes.
 *
 * Labelling: the three vertical planes F1, F2, F3 form a triangular prism; F_k is the side of the
 * triangle opposite its corner V_k. Sphere S_k sits in corner V_k and meets the two planes through
 * V_k, F_{k+1} and F_{k+2} (indices mod 3), and the other two spheres.
 */

/** Shape parameters (zb, zc) at which the type is a valid sphairahedron: the node's starting point and the tests'. */
type Example = readonly [number, number];

export interface CubeTypeAngles {
  readonly kind: 'cube';
  /** Stable id used in documents. */
  readonly id: string;
  /** What the picker shows. */
  readonly label: string;
  /** n of the prism's angle π/n at the corners V1, V2, V3 (a Euclidean triangle: Σ 1/n = 1). */
  readonly prism: readonly [number, number, number];
  /** For S_k: n of its angle π/n with F_{k+1}, then with F_{k+2}. */
  readonly spherePlane: readonly [
    readonly [number, number],
    readonly [number, number],
    readonly [number, number],
  ];
  /** n of the angle π/n between S1–S2, S2–S3, S3–S1. */
  readonly sphereSphere: readonly [number, number, number];
  readonly example: Example;
}

/** The cube types, in the published order (the letters F and G do not occur there). */
export const CUBE_TYPES: readonly CubeTypeAngles[] = [
  {
    kind: 'cube',
    id: 'cube-a',
    label: 'cube A · prism 333 · all π/3',
    prism: [3, 3, 3],
    spherePlane: [
      [3, 3],
      [3, 3],
      [3, 3],
    ],
    sphereSphere: [3, 3, 3],
    example: [0, 0],
  },
  {
    kind: 'cube',
    id: 'cube-b',
    label: 'cube B · prism 333 · S1 π/6, π/2',
    prism: [3, 3, 3],
    spherePlane: [
      [6, 2],
      [3, 3],
      [3, 3],
    ],
    sphereSphere: [6, 3, 2],
    example: [0.2, 0.2],
  },
  {
    kind: 'cube',
    id: 'cube-c',
    label: 'cube C · prism 333 · S1, S2 π/6, π/2',
    prism: [3, 3, 3],
    spherePlane: [
      [6, 2],
      [6, 2],
      [3, 3],
    ],
    sphereSphere: [3, 6, 2],
    example: [0.2, 0.2],
  },
  {
    kind: 'cube',
    id: 'cube-d',
    label: 'cube D · prism 236 · S1 π/3, π/6',
    prism: [2, 3, 6],
    spherePlane: [
      [3, 6],
      [3, 3],
      [2, 3],
    ],
    sphereSphere: [2, 6, 3],
    example: [0.1, 0.3],
  },
  {
    kind: 'cube',
    id: 'cube-e',
    label: 'cube E · prism 236 · S1 π/6, π/3',
    prism: [2, 3, 6],
    spherePlane: [
      [6, 3],
      [2, 6],
      [2, 3],
    ],
    sphereSphere: [6, 3, 2],
    example: [0.2, 0.2],
  },
  {
    kind: 'cube',
    id: 'cube-h',
    label: 'cube H · prism 244 · S3 π/2, π/4',
    prism: [2, 4, 4],
    spherePlane: [
      [4, 4],
      [2, 4],
      [2, 4],
    ],
    sphereSphere: [4, 4, 2],
    example: [0.2, 0.2],
  },
  {
    kind: 'cube',
    id: 'cube-i',
    label: 'cube I · prism 244 · S3 π/4, π/2',
    prism: [2, 4, 4],
    spherePlane: [
      [4, 4],
      [2, 4],
      [4, 2],
    ],
    sphereSphere: [4, 2, 4],
    example: [0.8, 0.8],
  },
  {
    // Not in the published list: an ideal angle assignment of the 236 prism kept from the first
    // table (Figs. 28–29's example uses it); the tests check it like the others.
    kind: 'cube',
    id: 'cube-236-a',
    label: 'cube · prism 236 · all spheres π/3 (not in the published list)',
    prism: [2, 3, 6],
    spherePlane: [
      [3, 6],
      [2, 6],
      [2, 3],
    ],
    sphereSphere: [3, 3, 3],
    example: [0.1, 0.3],
  },
  // The first table's other ideal assignments with no published twin: kept so documents made with
  // them still open as they were (the renamed ones migrate: sphairahedron node version 2).
  {
    kind: 'cube',
    id: 'cube-333-b',
    label: 'cube · prism 333 · one sphere π/2, π/6 (earlier Kleinflow, not in the published list)',
    prism: [3, 3, 3],
    spherePlane: [
      [2, 6],
      [3, 3],
      [3, 3],
    ],
    sphereSphere: [2, 3, 6],
    example: [0, 0],
  },
  {
    kind: 'cube',
    id: 'cube-333-c',
    label: 'cube · prism 333 · two spheres π/2, π/6 (earlier Kleinflow, not in the published list)',
    prism: [3, 3, 3],
    spherePlane: [
      [2, 6],
      [2, 6],
      [3, 3],
    ],
    sphereSphere: [3, 2, 6],
    example: [0, 0],
  },
  {
    kind: 'cube',
    id: 'cube-333-d',
    label: 'cube · prism 333 · three spheres π/2, π/6 (earlier Kleinflow, not in the published list)',
    prism: [3, 3, 3],
    spherePlane: [
      [2, 6],
      [2, 6],
      [2, 6],
    ],
    sphereSphere: [3, 3, 3],
    example: [0, 0],
  },
  {
    kind: 'cube',
    id: 'cube-236-b',
    label: 'cube · prism 236 · sphere angles π/6 … π/2 (earlier Kleinflow, not in the published list)',
    prism: [2, 3, 6],
    spherePlane: [
      [6, 3],
      [3, 3],
      [2, 3],
    ],
    sphereSphere: [3, 6, 2],
    example: [0, 0],
  },
];

/**
 * The pentahedral prism (a triangular prism's combinatorics, five faces) with a vertex at
 * infinity: the three prism planes, a central sphere S_m meeting all three, and a corner sphere
 * S_c in corner V1 meeting F2, F3 and S_m. One shape parameter: the central sphere's height.
 */
export interface PentahedralPrismAngles {
  readonly kind: 'pentahedral-prism';
  readonly id: string;
  readonly label: string;
  readonly prism: readonly [number, number, number];
  /** n of S_m's angle π/n with F1, F2, F3. */
  readonly central: readonly [number, number, number];
  /** n of S_c's angle π/n with F2, then F3. */
  readonly corner: readonly [number, number];
  /** n of the angle π/n between S_c and S_m. */
  readonly sphereSphere: number;
  readonly example: Example;
}

/** The pentahedral prisms, in the published order. */
export const PENTAHEDRAL_TYPES: readonly PentahedralPrismAngles[] = [
  {
    kind: 'pentahedral-prism',
    id: 'prism-a',
    label: 'pentahedral prism A · prism 333 · all π/3',
    prism: [3, 3, 3],
    central: [3, 3, 3],
    corner: [3, 3],
    sphereSphere: 3,
    example: [0.8, 0],
  },
  {
    kind: 'pentahedral-prism',
    id: 'prism-b',
    label: 'pentahedral prism B · prism 333 · central π/2, π/6, π/6',
    prism: [3, 3, 3],
    central: [2, 6, 6],
    corner: [3, 3],
    sphereSphere: 2,
    example: [0.8, 0],
  },
  {
    kind: 'pentahedral-prism',
    id: 'prism-c',
    label: 'pentahedral prism C · prism 333 · central π/6, π/2, π/2',
    prism: [3, 3, 3],
    central: [6, 2, 2],
    corner: [3, 3],
    sphereSphere: 6,
    example: [1.9, 0],
  },
  {
    kind: 'pentahedral-prism',
    id: 'prism-d',
    label: 'pentahedral prism D · prism 236 · central π/2, π/3, π/6',
    prism: [2, 3, 6],
    central: [2, 3, 6],
    corner: [6, 3],
    sphereSphere: 2,
    example: [0.8, 0],
  },
  {
    kind: 'pentahedral-prism',
    id: 'prism-e',
    label: 'pentahedral prism E · prism 244 · central π/4, π/2, π/2',
    prism: [2, 4, 4],
    central: [4, 2, 2],
    corner: [4, 4],
    sphereSphere: 4,
    example: [1.7, 0],
  },
  {
    kind: 'pentahedral-prism',
    id: 'prism-f',
    label: 'pentahedral prism F · prism 244 · central π/2, π/4, π/4',
    prism: [2, 4, 4],
    central: [2, 4, 4],
    corner: [4, 4],
    sphereSphere: 2,
    example: [0.8, 0],
  },
];

/**
 * The cake (six faces): a rectangular prism of four planes — the ends F1, F3 and the long sides
 * F2, F4, all corners π/2 — closed below by two spheres: S1 at the F1 end meets F1, F2, F4, S2 at
 * the F3 end meets F3, F2, F4, and the two meet each other. One shape parameter: S2's height zb
 * (S1 at 0); the rectangle's width follows from it.
 */
export interface CakeAngles {
  readonly kind: 'cake';
  readonly id: string;
  readonly label: string;
  /** n of S1's angle π/n with its end F1, then with F2, F4. */
  readonly first: readonly [number, number, number];
  /** n of S2's angle π/n with its end F3, then with F2, F4. */
  readonly second: readonly [number, number, number];
  /** n of the angle π/n between S1 and S2. */
  readonly sphereSphere: number;
  readonly example: Example;
}

/** The cakes, in the published order. */
export const CAKE_TYPES: readonly CakeAngles[] = [
  {
    kind: 'cake',
    id: 'cake-a',
    label: 'cake A · S1 π/6, π/3, π/3 · S2 π/3, π/6, π/6',
    first: [6, 3, 3],
    second: [3, 6, 6],
    sphereSphere: 2,
    example: [0.3, 0],
  },
  {
    kind: 'cake',
    id: 'cake-b',
    label: 'cake B · all spheres π/4',
    first: [4, 4, 4],
    second: [4, 4, 4],
    sphereSphere: 2,
    example: [0.3, 0],
  },
  {
    kind: 'cake',
    id: 'cake-c',
    label: 'cake C · S1, S2 π/6, π/3, π/3',
    first: [6, 3, 3],
    second: [6, 3, 3],
    sphereSphere: 3,
    example: [0.3, 0],
  },
];

export type SphairahedronType = CubeTypeAngles | PentahedralPrismAngles | CakeAngles;

export const SPHAIRAHEDRON_TYPES: readonly SphairahedronType[] = [
  ...CUBE_TYPES,
  ...PENTAHEDRAL_TYPES,
  ...CAKE_TYPES,
];

export const SPHAIRAHEDRON_TYPE_IDS = SPHAIRAHEDRON_TYPES.map((t) => t.id);

export const sphairahedronTypeById = (id: string): SphairahedronType | undefined =>
  SPHAIRAHEDRON_TYPES.find((t) => t.id === id);
