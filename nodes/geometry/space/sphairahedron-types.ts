/**
 * The cube-type sphairahedra with a vertex at infinity: which dihedral angle π/n sits on which edge
 * (docs/math-3d.md "Sphairahedra (paper §5.3)"). Only angles are listed here; the shapes are built
 * by sphairahedron.ts.
 *
 * Labelling: the three vertical planes F1, F2, F3 form a triangular prism; F_k is the side of the
 * triangle opposite its corner V_k. Sphere S_k sits in corner V_k and meets the two planes through
 * V_k, F_{k+1} and F_{k+2} (indices mod 3), and the other two spheres.
 */

export interface CubeTypeAngles {
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

export const CUBE_TYPE_IDS = CUBE_TYPES.map((t) => t.id);

export const cubeTypeById = (id: string): CubeTypeAngles | undefined => CUBE_TYPES.find((t) => t.id === id);
