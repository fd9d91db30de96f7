/**
 * The loop period of an animated graph: the shortest time L > 0 after which every time-driven
 * value repeats, so a recording of [0, L) played in a loop has no seam (frame L meets frame 0).
 *
 * Time enters a graph only through Time nodes (output = seconds × speed). A Sine wave or Circular
 * motion whose `t` input is wired straight from a Time node is periodic in seconds with period
 * P/|speed|; everything downstream of those is a function of periodic signals, so the graph repeats
 * after the least common multiple of those periods. The LCM exists when the periods are rational
 * multiples of each other: with P_i = a_i/b_i in lowest terms, lcm = lcm(a_i) / gcd(b_i).
 * A Time output wired anywhere else (a rotation angle, a sine's period…) grows without bound, so
 * the graph has no loop; that is reported with the node to blame, never guessed. So is a formula
 * (Formula, Seed shape) that reads the time t itself: t grows without bound there too.
 */
import { FORMULA_NODE_TYPES, formulaUses } from '../formula/names.ts';
import type { GraphDoc } from './document.ts';
import type { Evaluation } from './evaluate.ts';

/** The node types whose `t` input turns seconds into a cycle (nodes/types/animation.ts). */
const CYCLE_TYPES: ReadonlySet<string> = new Set(['sine', 'circular-motion']);
const TIME_TYPE = 'time';
/** Longer than this is "no common loop" for a recording: an hour of frames is not a loop anyone exports. */
export const MAX_LOOP_SECONDS = 3600;
/** Periods are read as fractions with denominators up to this (0.1 s steps and thirds both fit). */
const MAX_DENOMINATOR = 10_000;

export interface CycleSource {
  /** The Sine wave / Circular motion node. */
  readonly nodeId: string;
  /** Its period in seconds of animation time: period / |speed of its Time node|. */
  readonly seconds: number;
}

export type LoopPeriod =
  /** Nothing depends on time: every frame is the same picture. */
  | { readonly kind: 'static' }
  | { readonly kind: 'loop'; readonly seconds: number; readonly sources: readonly CycleSource[] }
  | { readonly kind: 'none'; readonly reason: string; readonly nodeId?: string };

/** x as a fraction num/den in lowest terms (den ≤ MAX_DENOMINATOR), or null when none is that close. */
export function asFraction(x: number): { num: number; den: number } | null {
  if (!Number.isFinite(x) || x <= 0) return null;
  // Continued-fraction convergents h/k of x, stopping at the first that matches to 1e-9 relative.
  let [h0, h1, k0, k1] = [0, 1, 1, 0];
  let rest = x;
  for (let i = 0; i < 40; i++) {
    const a = Math.floor(rest);
    [h0, h1] = [h1, a * h1 + h0];
    [k0, k1] = [k1, a * k1 + k0];
    if (k1 > MAX_DENOMINATOR) return null;
    if (Math.abs(h1 / k1 - x) <= 1e-9 * x) return { num: h1, den: k1 };
    const frac = rest - a;
    if (frac < 1e-12) break;
    rest = 1 / frac;
  }
  return Math.abs(h1 / k1 - x) <= 1e-9 * x ? { num: h1, den: k1 } : null;
}

const gcd = (a: number, b: number): number => (b === 0 ? a : gcd(b, a % b));

/** The least common multiple of positive periods, or null when they have none within MAX_LOOP_SECONDS. */
export function commonPeriod(periods: readonly number[]): number | null {
  let num = 0;
  let den = 0;
  for (const p of periods) {
    const f = asFraction(p);
    if (!f) return null;
    if (num === 0) [num, den] = [f.num, f.den];
    else {
      num = (num / gcd(num, f.num)) * f.num;
      den = gcd(den, f.den);
    }
    if (num / den > MAX_LOOP_SECONDS) return null;
  }
  return num === 0 ? null : num / den;
}

const label = (doc: GraphDoc, id: string): string => {
  const n = doc.nodes.find((m) => m.id === id);
  return `"${n?.label ?? id}"`;
};

/** Every node that depends on some Time node's output (the Time nodes excluded). */
function timeDriven(doc: GraphDoc): Set<string> {
  const driven = new Set<string>();
  const frontier = doc.nodes.filter((n) => n.type === TIME_TYPE).map((n) => n.id);
  while (frontier.length) {
    const id = frontier.pop()!;
    for (const e of doc.edges) {
      if (e.from.node === id && !driven.has(e.to.node)) {
        driven.add(e.to.node);
        frontier.push(e.to.node);
      }
    }
  }
  return driven;
}

/**
 * The loop period of `doc`, reading periods and speeds from `evaluation` (any time: a period that
 * is itself time-driven is reported as no loop, so the value at that time is the value always).
 */
export function loopPeriod(doc: GraphDoc, evaluation: Evaluation): LoopPeriod {
  const types = new Map(doc.nodes.map((n) => [n.id, n.type]));
  const driven = timeDriven(doc);
  const input = (id: string, port: string): unknown => evaluation.nodes.get(id)?.ctx?.inputs[port];
  const wiredFromDriven = (id: string, port: string): boolean =>
    doc.edges.some(
      (e) =>
        e.to.node === id &&
        e.to.port === port &&
        (driven.has(e.from.node) || types.get(e.from.node) === TIME_TYPE),
    );
  const clock = doc.nodes.find(
    (n) =>
      FORMULA_NODE_TYPES.has(n.type) &&
      typeof n.params?.formula === 'string' &&
      formulaUses(n.params.formula, 't'),
  );
  if (clock)
    return {
      kind: 'none',
      nodeId: clock.id,
      reason: `${label(doc, clock.id)} reads the time t in its formula, so the animation never repeats: wire a Sine wave or Circular motion into its a, b, c, p or q instead`,
    };
  const sources: CycleSource[] = [];
  for (const e of doc.edges) {
    if (types.get(e.from.node) !== TIME_TYPE) continue;
    const target = e.to.node;
    if (!CYCLE_TYPES.has(types.get(target) ?? '') || e.to.port !== 't')
      return {
        kind: 'none',
        nodeId: target,
        reason: `${label(doc, target)} uses the time directly (not through a Sine wave or Circular motion), so the animation never repeats`,
      };
    if (wiredFromDriven(e.from.node, 'speed'))
      return {
        kind: 'none',
        nodeId: e.from.node,
        reason: `the speed of ${label(doc, e.from.node)} changes with time, so the animation never repeats`,
      };
    if (wiredFromDriven(target, 'period'))
      return {
        kind: 'none',
        nodeId: target,
        reason: `the period of ${label(doc, target)} changes with time, so the animation never repeats`,
      };
    const speed = Math.abs(Number(input(e.from.node, 'speed')));
    const period = Number(input(target, 'period'));
    if (!(period > 0) || !Number.isFinite(speed))
      return { kind: 'none', nodeId: target, reason: `${label(doc, target)} has no valid period` };
    if (speed === 0) continue; // a stopped clock: this cycle stands still
    sources.push({ nodeId: target, seconds: period / speed });
  }
  if (sources.length === 0) return { kind: 'static' };
  const seconds = commonPeriod(sources.map((s) => s.seconds));
  if (seconds === null) {
    const list = sources.map((s) => `${label(doc, s.nodeId)} ${+s.seconds.toPrecision(6)} s`).join(', ');
    return {
      kind: 'none',
      reason: `no common loop: the periods (${list}) do not line up within ${MAX_LOOP_SECONDS} s`,
    };
  }
  return { kind: 'loop', seconds, sources };
}
