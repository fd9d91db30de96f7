/**
 * Flower's OrbitSeed → Kleinflow's `seed-image`: a picture rectangle that the tile paints together
 * with all its images (the paper's Figs. 2 and 11). None of Flower's presets holds an OrbitSeed, so
 * its saved fields are not known for certain: they are read under the names Flower's sibling
 * programs use (a lower-left `corner` with `width` and `height`, an `origin`, a `pos`, or a
 * centre), and every guess and every gap becomes a note. Flower keeps its picture outside the
 * JSON, so Kleinflow's built-in picture stands in until the user wires an Image node.
 */
import type { FlowerNode } from './format.ts';
import { named, pickEntry, pickPoint } from './format.ts';
import type { MapContext, MappedNode } from './mapping.ts';

/** Flower's view is 100 units tall (view.ts): a seed with no saved size gets a tenth of it. */
export const FLOWER_SEED_SIZE = 10;

/** Which seed-image input each Flower input socket feeds, by socket type, in order of appearance. */
const INPUT_PORTS: Readonly<Record<string, readonly string[]>> = {
  Point: ['center'],
  Float: ['width', 'height'],
};

const CENTRE_NAMES = ['center', 'centre'];
/** Fields that place the rectangle by its lower-left corner (before rotation). */
const CORNER_NAMES = ['corner', 'origin', 'pos', 'position'];
const RADIAN_KEYS = ['rotationRadians', 'rotationRad', 'rotation', 'angle', 'theta'];
const DEGREE_KEYS = ['rotationDegrees', 'rotationDeg', 'angleDeg'];

/** Kleinflow input per Flower input socket: the n-th socket of a type gets INPUT_PORTS[type][n]. */
function inputPorts(node: FlowerNode): (string | null)[] {
  const seen = new Map<string, number>();
  return node.sockets
    .filter((s) => !s.isOutput)
    .map((s) => {
      const n = seen.get(s.name) ?? 0;
      seen.set(s.name, n + 1);
      return INPUT_PORTS[s.name]?.[n] ?? null;
    });
}

type Entry = { key: string; value: number };

/** Saved signed width and height (a negative one extends left/down of the corner), when non-zero. */
function readSize(node: FlowerNode): { width?: Entry; height?: Entry } {
  const size = pickPoint(node, 'size');
  const side = size ? undefined : pickEntry(node, 'size');
  const fromSize = (k: 0 | 1) => (size ? { key: 'size', value: size.value[k] } : side);
  const width = pickEntry(node, 'width', 'w', 'renderWidth') ?? fromSize(0);
  let height = pickEntry(node, 'height', 'h') ?? fromSize(1);
  const aspect = pickEntry(node, 'aspect');
  if (!height && width && aspect)
    height = { key: `${width.key} × aspect`, value: width.value * aspect.value };
  const usable = (e: Entry | undefined) => (e && e.value !== 0 ? e : undefined);
  return { width: usable(width), height: usable(height) };
}

/** The rotation in radians (0 when none is saved) and the field it came from. */
function readRotation(node: FlowerNode): { theta: number; key?: string } {
  const rad = pickEntry(node, ...RADIAN_KEYS);
  if (rad) return { theta: rad.value, key: `${rad.key} (radians)` };
  const deg = pickEntry(node, ...DEGREE_KEYS);
  return deg ? { theta: (deg.value * Math.PI) / 180, key: `${deg.key} (degrees)` } : { theta: 0 };
}

export function mapOrbitSeed(node: FlowerNode, ctx: MapContext): MappedNode {
  const inputs = inputPorts(node);
  const wiredPorts = new Set(inputs.filter((port, i) => port !== null && ctx.wired.has(i)));
  const { width, height } = readSize(node);
  // One saved side makes a square; none gives Flower-sized default.
  const w = width?.value ?? height?.value ?? FLOWER_SEED_SIZE;
  const h = height?.value ?? width?.value ?? FLOWER_SEED_SIZE;
  const { theta, key: rotationKey } = readRotation(node);
  const [cos, sin] = [Math.cos(theta), Math.sin(theta)];

  // Centre = corner + R(θ)(w/2, h/2): the rectangle turns about its corner, as it is placed by it.
  const centre = pickPoint(node, ...CENTRE_NAMES);
  const corner = centre ? undefined : pickPoint(node, ...CORNER_NAMES);
  const center: [number, number] = centre
    ? centre.value
    : corner
      ? [corner.value[0] + cos * (w / 2) - sin * (h / 2), corner.value[1] + sin * (w / 2) + cos * (h / 2)]
      : [0, 0];

  const who = named(node);
  const sources = [
    centre ? `${centre.key} as its centre` : corner ? `${corner.key} as its lower-left corner` : '',
    ...new Set([width?.key, height?.key]),
    rotationKey,
  ].filter((k): k is string => Boolean(k));
  const notes = [
    `${who}: Flower's seed picture is not carried over; Kleinflow's built-in picture stands in (wire an Image node into the seed's "picture")`,
  ];
  if (sources.length > 0) {
    notes.push(
      `${who}: no Flower preset has an OrbitSeed, so its fields are guessed: the seed rectangle was read from ${sources.join(', ')}`,
    );
  }
  if (wiredPorts.has('center')) {
    notes.push(
      `${who}: the point wired into it sets the seed's centre (Flower may place the seed by its corner)`,
    );
  } else if (!centre && !corner) {
    notes.push(`${who}: no saved position found; the seed is placed at the origin`);
  }
  const unknown = (['width', 'height'] as const).filter(
    (dim) => !{ width, height }[dim] && !wiredPorts.has(dim),
  );
  if (unknown.length === 2) {
    notes.push(
      `${who}: no saved width or height found; a ${FLOWER_SEED_SIZE} × ${FLOWER_SEED_SIZE} square (a tenth of Flower's view) is used`,
    );
  } else if (unknown.length === 1) {
    notes.push(`${who}: no saved ${unknown[0]} found; the seed is made square`);
  }
  if (ctx.consumers.length > 0) {
    notes.push(
      `${who}: its output feeds ${ctx.consumers.join(', ')}; a Kleinflow seed feeds only the tile, so those edges are dropped`,
    );
  }
  return {
    type: 'seed-image',
    prefix: 'O',
    params: { center, width: Math.abs(w), height: Math.abs(h), rotation: (theta * 180) / Math.PI },
    inputs,
    outputs: node.sockets.filter((s) => s.isOutput).map(() => null),
    seed: true,
    notes,
  };
}
