/**
 * The sphairahedra with a vertex at infinity — cube type and pentahedral prism: which dihedral angle π/n sits on which edge
 * (docs/math-3d.md "Sphairahedra (paper §5.3)"). Only angles are listed here; the shapes are built
 * by sphairahedron.ts.
 *
 * Labelling: the three vertical planes F1, F2, F3 form a triangular prism; F_k is the side of the
 * triangle opposite its corner V_k. Sphere S_k sits in corner V_k and meets the two planes through
 * V_k, F_{k+1} and F_{k+2} (indices mod 3), and the other two spheres.
 */

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
}

/**
 * A selection of the angle assignments that make every vertex ideal (at each vertex the three
 * angles sum to π), covering the three Euclidean prisms 333, 244 and 236. The test checks the
 * vertex sums of every entry and that each one builds for the default shape parameters.
 */
export const CUBE_TYPES: readonly CubeTypeAngles[] = [
  {
    kind: 'cube',
    id: 'cube-333-a',
    label: 'cube · prism 333 · all π/3',
    prism: [3, 3, 3],
    spherePlane: [
      [3, 3],
      [3, 3],
      [3, 3],
    ],
    sphereSphere: [3, 3, 3],
  },
  {
    kind: 'cube',
    id: 'cube-333-b',
    label: 'cube · prism 333 · one sphere π/2, π/6',
    prism: [3, 3, 3],
    spherePlane: [
      [2, 6],
      [3, 3],
      [3, 3],
    ],
    sphereSphere: [2, 3, 6],
  },
  {
    kind: 'cube',
    id: 'cube-333-c',
    label: 'cube · prism 333 · two spheres π/2, π/6',
    prism: [3, 3, 3],
    spherePlane: [
      [2, 6],
      [2, 6],
      [3, 3],
    ],
    sphereSphere: [3, 2, 6],
  },
  {
    kind: 'cube',
    id: 'cube-333-d',
    label: 'cube · prism 333 · three spheres π/2, π/6',
    prism: [3, 3, 3],
    spherePlane: [
      [2, 6],
      [2, 6],
      [2, 6],
    ],
    sphereSphere: [3, 3, 3],
  },
  {
    kind: 'cube',
    id: 'cube-244-a',
    label: 'cube · prism 244 · π/4 spheres',
    prism: [2, 4, 4],
    spherePlane: [
      [4, 4],
      [2, 4],
      [2, 4],
    ],
    sphereSphere: [4, 4, 2],
  },
  {
    kind: 'cube',
    id: 'cube-236-a',
    label: 'cube · prism 236 · all spheres π/3',
    prism: [2, 3, 6],
    spherePlane: [
      [3, 6],
      [2, 6],
      [2, 3],
    ],
    sphereSphere: [3, 3, 3],
  },
  {
    kind: 'cube',
    id: 'cube-236-b',
    label: 'cube · prism 236 · sphere angles π/6 … π/2',
    prism: [2, 3, 6],
    spherePlane: [
      [6, 3],
      [3, 3],
      [2, 3],
    ],
    sphereSphere: [3, 6, 2],
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
}

/** Ideal angle assignments of the pentahedral prism (every vertex sum π; checked by the test). */
export const PENTAHEDRAL_TYPES: readonly PentahedralPrismAngles[] = [
  {
    kind: 'pentahedral-prism',
    id: 'prism-333-a',
    label: 'pentahedral prism · prism 333 · all π/3',
    prism: [3, 3, 3],
    central: [3, 3, 3],
    corner: [3, 3],
    sphereSphere: 3,
  },
  {
    kind: 'pentahedral-prism',
    id: 'prism-333-b',
    label: 'pentahedral prism · prism 333 · central sphere π/2, π/6, π/6',
    prism: [3, 3, 3],
    central: [2, 6, 6],
    corner: [3, 3],
    sphereSphere: 2,
  },
  {
    kind: 'pentahedral-prism',
    id: 'prism-244-a',
    label: 'pentahedral prism · prism 244 · central sphere π/2, π/4, π/4',
    prism: [2, 4, 4],
    central: [2, 4, 4],
    corner: [4, 4],
    sphereSphere: 2,
  },
];

export type SphairahedronType = CubeTypeAngles | PentahedralPrismAngles;

export const SPHAIRAHEDRON_TYPES: readonly SphairahedronType[] = [...CUBE_TYPES, ...PENTAHEDRAL_TYPES];

export const SPHAIRAHEDRON_TYPE_IDS = SPHAIRAHEDRON_TYPES.map((t) => t.id);

export const sphairahedronTypeById = (id: string): SphairahedronType | undefined =>
  SPHAIRAHEDRON_TYPES.find((t) => t.id === id);
