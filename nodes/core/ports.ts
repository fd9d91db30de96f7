/**
 * Port (socket) types: the single table that the UI (colours, connection rules), the validator
 * and the evaluator read.
 */
export const PORT_TYPES = [
  'number',
  'point',
  'line',
  'circle',
  'element',
  'tile',
  'color',
  'image',
  'seed',
  // Space (docs/math-3d.md): distinct from the plane's types, so a 3D element never wires into the
  // 2D render (or the reverse): the connection is refused as a type mismatch.
  'point3',
  'sphere',
  'plane',
  'element3',
  'seed3',
  'limit3',
] as const;
export type PortType = (typeof PORT_TYPES)[number];

interface PortTypeInfo {
  /** Colour of sockets and wires of this type in the editor. */
  readonly color: string;
  /** Whether an input of this type takes many edges (their values are concatenated). */
  readonly many: boolean;
  /** Output types that may be wired into an input of this type (besides itself). */
  readonly accepts: readonly PortType[];
  readonly doc: string;
}

/** No other type converts into this one. */
const ONLY_ITSELF: readonly PortType[] = [];

// `satisfies` (not a type annotation) keeps each `many` literal, from which ManyPortType is derived.
export const PORT_TYPE_INFO = {
  number: { color: '#9aa5b1', many: false, accepts: ONLY_ITSELF, doc: 'a real number' },
  point: { color: '#f2c14e', many: false, accepts: ONLY_ITSELF, doc: 'a point of the plane' },
  line: { color: '#4ecdc4', many: false, accepts: ONLY_ITSELF, doc: 'a directed line (keeps its left side)' },
  circle: { color: '#5b8def', many: false, accepts: ONLY_ITSELF, doc: 'a circle (centre and radius)' },
  element: {
    color: '#e85d75',
    many: true,
    accepts: ONLY_ITSELF,
    doc: 'one or more IIS elements (mirrors, generators)',
  },
  tile: {
    color: '#b07cf0',
    many: false,
    accepts: ONLY_ITSELF,
    doc: 'how the tile and its images are coloured',
  },
  color: { color: '#f08a5d', many: false, accepts: ONLY_ITSELF, doc: 'an sRGB colour' },
  image: { color: '#7bc96f', many: false, accepts: ONLY_ITSELF, doc: 'a picture' },
  seed: {
    color: '#e0b0ff',
    many: true,
    accepts: ONLY_ITSELF,
    doc: 'one or more orbit seeds (disks or picture rectangles) whose images the tile paints',
  },
  point3: { color: '#f7dc6f', many: false, accepts: ONLY_ITSELF, doc: 'a point of space (x, y, z)' },
  sphere: {
    color: '#3fa7d6',
    many: false,
    accepts: ONLY_ITSELF,
    doc: 'a sphere in space (centre and radius)',
  },
  plane: {
    color: '#2bb3a3',
    many: false,
    accepts: ONLY_ITSELF,
    doc: 'a plane in space (a point and a normal; a mirror keeps the side the normal points to)',
  },
  element3: {
    color: '#c2185b',
    many: true,
    accepts: ONLY_ITSELF,
    doc: 'one or more 3D IIS elements (sphere inversions, plane reflections, 3D generators)',
  },
  seed3: {
    color: '#ba68c8',
    many: true,
    accepts: ONLY_ITSELF,
    doc: 'one or more 3D orbit seeds (spheres, boxes) whose images the 3D render draws',
  },
  limit3: {
    color: '#ff8a65',
    many: true,
    accepts: ONLY_ITSELF,
    doc: 'one or more quaternion Kleinian groups whose limit sets the 3D render draws as dots',
  },
} satisfies Readonly<Record<PortType, PortTypeInfo>>;

/** The types whose inputs take many edges (element, seed): they receive one flat array. */
export type ManyPortType = {
  [T in PortType]: (typeof PORT_TYPE_INFO)[T]['many'] extends true ? T : never;
}[PortType];

/** Whether an output of type `from` may be connected to an input of type `to`. */
export function canConnect(from: PortType, to: PortType): boolean {
  return from === to || PORT_TYPE_INFO[to].accepts.includes(from);
}

export function isPortType(s: string): s is PortType {
  return (PORT_TYPES as readonly string[]).includes(s);
}
