/**
 * How each of Flower's 11 node types becomes a Kleinflow node. One entry per Flower type: the
 * Kleinflow type, its params, which Kleinflow port each Flower input/output socket (by order among
 * the node's inputs/outputs) corresponds to, and whether it is a mirror. Types whose Kleinflow twin
 * is not registered fall back to a snapshot of their saved value or are skipped, with a note.
 *
 * Facts about Flower used here: a Point's first Float input drives y and its second drives x
 * (posX/posY hold the position); LineTwoPoints runs from its first input point p1 to p2 and a
 * LineMirror keeps the LEFT side of p1→p2 (`reverse` keeps the right: Kleinflow's `flip`);
 * CircleMirror inverts in its circle; both mirrors pass their input through to their output.
 * OrbitSeed (a picture rectangle whose images are painted) becomes a seed picture wired into the
 * tile; its saved fields are guessed (orbit-seed.ts).
 */
import { type FlowerNode, finite, named, pick } from './format.ts';
import type { FlowerTypeMap, MapContext, Mapping } from './mapping.ts';
import { mapOrbitSeed } from './orbit-seed.ts';

/** Inputs that Flower leaves at (0, 0) when unwired; Kleinflow uses its defaults and says so. */
function unwiredPoints(node: FlowerNode, ctx: MapContext, ports: readonly string[]): string[] {
  const missing = ports.filter((_, i) => !ctx.wired.has(i));
  if (missing.length === 0) return [];
  return [
    `${named(node)} has no point wired into ${missing.map((p) => `"${p}"`).join(', ')}; Kleinflow's default is used and the node is hidden`,
  ];
}

/** A constant stand-in for a Flower value node whose animated Kleinflow twin is missing. */
function snapshot(node: FlowerNode, value: unknown, what: string): Mapping {
  if (!finite(value)) return { skip: `${named(node)} cannot be mapped yet (Kleinflow has no ${what} node)` };
  return {
    type: 'number',
    prefix: 'N',
    params: { value },
    inputs: [],
    outputs: [{ port: 'value' }],
    notes: [
      `${named(node)} cannot be mapped yet (Kleinflow has no ${what} node): imported as a Number holding its saved value ${value}; the animation is lost`,
    ],
  };
}

export const FLOWER_NODE_TYPES: Readonly<Record<string, FlowerTypeMap>> = {
  Constant: (node) => ({
    type: 'number',
    prefix: 'N',
    params: { value: finite(node.raw.value) ? node.raw.value : 1 },
    inputs: [],
    outputs: [{ port: 'value' }],
    notes: [],
  }),
  Point: (node) => {
    const { posX, posY } = node.raw;
    const known = finite(posX) && finite(posY);
    return {
      type: 'point',
      prefix: 'P',
      params: { x: known ? posX : 0, y: known ? posY : 0 },
      inputs: ['y', 'x'],
      outputs: [{ port: 'point' }],
      notes: known ? [] : [`${named(node)} has no saved position (posX, posY); it is placed at (0, 0)`],
    };
  },
  LineTwoPoints: (node, ctx) => {
    const notes = unwiredPoints(node, ctx, ['a', 'b']);
    return {
      type: 'line',
      prefix: 'L',
      params: notes.length > 0 ? { visible: false } : {},
      inputs: ['a', 'b'],
      outputs: [{ port: 'line' }],
      notes,
    };
  },
  LineMirror: (node, ctx) =>
    ctx.wired.has(0)
      ? {
          type: 'reflection',
          prefix: 'M',
          params: { flip: node.raw.reverse === true },
          inputs: ['line'],
          outputs: [{ passthroughInput: 0 }],
          mirror: 'line',
          notes: [],
        }
      : { skip: `${named(node)} has no line wired in, so it mirrors nothing; skipped` },
  CircleThreePoints: (node, ctx) => {
    const notes = unwiredPoints(node, ctx, ['a', 'b', 'c']);
    return {
      type: 'circle-3pt',
      prefix: 'C',
      params: notes.length > 0 ? { visible: false } : {},
      inputs: ['a', 'b', 'c'],
      outputs: [{ port: 'circle' }],
      notes,
    };
  },
  CircleMirror: (node, ctx) =>
    ctx.wired.has(0)
      ? {
          type: 'inversion',
          prefix: 'M',
          params: {},
          inputs: ['circle'],
          outputs: [{ passthroughInput: 0 }],
          mirror: 'circle',
          notes: [],
        }
      : { skip: `${named(node)} has no circle wired in, so it inverts in nothing; skipped` },
  SinWave: (node, ctx) =>
    ctx.registry.get('sine') ? mapSine(node) : snapshot(node, node.raw.value, 'sine-wave'),
  CircularMotion: (node, ctx) =>
    ctx.registry.get('circular-motion')
      ? mapCircularMotion(node)
      : {
          skip: `${named(node)} cannot be mapped yet (Kleinflow has no circular-motion node); what it drives keeps its saved values`,
        },
  Vec3: (node, ctx) => {
    if (ctx.consumers.length > 0 && ctx.consumers.every((c) => c === 'ColorPalettes')) {
      return ctx.wired.size === 0
        ? { skip: null }
        : {
            skip: `${named(node)} has wired inputs; the palette uses its saved values (the animation is lost)`,
          };
    }
    return { skip: `${named(node)} cannot be mapped (Kleinflow uses Vec3 values only as palette colours)` };
  },
  // Its palette becomes the imported tile's colouring (import.ts, palette.ts).
  ColorPalettes: () => ({ skip: null }),
  OrbitSeed: (node, ctx) =>
    ctx.registry.get('seed-image')
      ? mapOrbitSeed(node, ctx)
      : {
          skip: `${named(node)} cannot be mapped yet (Kleinflow has no orbit-seed node); the picture shows no seed`,
        },
};

/** Flower's periods are in milliseconds (its presets use 1000); Kleinflow's in seconds. */
const MS = 1000;

/**
 * SinWave (amplitude, period, phaseShift, offset) → Kleinflow's `sine` node, whose inputs have
 * the same meaning (offset + amplitude·sin(2π t/period + phase)), driven by the shared Time node.
 */
function mapSine(node: FlowerNode): Mapping {
  const amplitude = pick(node, 'amplitude');
  const period = pick(node, 'period');
  const phase = pick(node, 'phaseShift', 'phase');
  const offset = pick(node, 'offset');
  return {
    type: 'sine',
    prefix: 'S',
    params: {
      ...(amplitude !== undefined ? { amplitude } : {}),
      ...(period !== undefined && period > 0 ? { period: period / MS } : {}),
      ...(phase !== undefined ? { phase } : {}),
      ...(offset !== undefined ? { offset } : {}),
    },
    inputs: [],
    outputs: [{ port: 'value' }],
    timeInput: 't',
    notes: [],
  };
}

/** CircularMotion → Kleinflow's `circular-motion` (centre, radius, period, phase), driven by Time. */
function mapCircularMotion(node: FlowerNode): Mapping {
  const cx = pick(node, 'centerX', 'posX', 'x0');
  const cy = pick(node, 'centerY', 'posY', 'y0');
  const radius = pick(node, 'radius', 'r');
  const period = pick(node, 'period');
  const phase = pick(node, 'phaseShift', 'phase');
  const missing = [
    cx === undefined || cy === undefined ? 'centre' : '',
    radius === undefined ? 'radius' : '',
    period === undefined ? 'period' : '',
  ].filter(Boolean);
  return {
    type: 'circular-motion',
    prefix: 'R',
    params: {
      ...(cx !== undefined && cy !== undefined ? { center: [cx, cy] } : {}),
      ...(radius !== undefined && radius >= 0 ? { radius } : {}),
      ...(period !== undefined && period > 0 ? { period: period / MS } : {}),
      ...(phase !== undefined ? { phase } : {}),
    },
    inputs: [],
    outputs: [{ port: 'point' }],
    timeInput: 't',
    notes: missing.length
      ? [`${named(node)}: no saved ${missing.join(', ')} found; Kleinflow's defaults are used`]
      : [],
  };
}
