/**
 * Animation: values that change with time. Only values change (they become uniforms); nothing in
 * the Scene's structure depends on time, so playing an animation never recompiles the shader.
 */
import { defineNode } from '../core/define-node.ts';
import type { Circle, Vec2 } from '../core/values.ts';
import { dist } from '../geometry/vec.ts';
import { fail, fmt, pointInput, VISIBLE } from './shared.ts';

const timeInput = {
  type: 'number' as const,
  label: 'time t',
  default: 0,
  step: 0.01,
  doc: 'seconds; wire a Time node to animate',
};
const periodInput = { type: 'number' as const, label: 'period (s)', default: 4, min: 0, step: 0.1 };
const phaseInput = { type: 'number' as const, label: 'phase (rad)', default: 0, step: 0.01 };
const noPeriod = (T: number) => fail(`the period must be positive, got ${fmt(T)}`);

export const timeNode = defineNode({
  type: 'time',
  version: 1,
  label: 'Time',
  category: 'Animation',
  color: '#9aa5b1',
  doc: 'Seconds since the animation started, times a speed (0 while not playing).',
  inputs: {
    speed: { type: 'number', label: 'speed', default: 1, step: 0.1, doc: 'output = seconds × speed' },
  },
  outputs: { time: { type: 'number', label: 'time' } },
  params: {},
  evaluate: ({ inputs, time }) => {
    const t = time * inputs.speed;
    return { outputs: { time: t }, readout: `t = ${fmt(t)}` };
  },
});

/** The angle of a cycle at time t: α = 2π·t/period + phase (radians). */
export const cycleAngle = (t: number, period: number, phase = 0): number =>
  2 * Math.PI * (t / period) + phase;

/** offset + amplitude·sin(2π·t/period + phase). */
export const sineWave = (
  t: number,
  period: number,
  amplitude: number,
  phase: number,
  offset: number,
): number => offset + amplitude * Math.sin(cycleAngle(t, period, phase));

export const sineNode = defineNode({
  type: 'sine',
  version: 1,
  label: 'Sine wave',
  category: 'Animation',
  color: '#9aa5b1',
  doc: 'offset + amplitude·sin(2π·t/period + phase): a value that swings back and forth.',
  inputs: {
    t: timeInput,
    period: periodInput,
    amplitude: { type: 'number', label: 'amplitude', default: 1, step: 0.01 },
    phase: phaseInput,
    offset: { type: 'number', label: 'offset', default: 0, step: 0.01 },
  },
  outputs: { value: { type: 'number', label: 'value' } },
  params: {},
  evaluate: ({ inputs }) => {
    const T = inputs.period;
    if (!(T > 0)) return noPeriod(T);
    const v = sineWave(inputs.t, T, inputs.amplitude, inputs.phase, inputs.offset);
    return { outputs: { value: v }, readout: fmt(v) };
  },
});

/** c + r·(cos α, sin α) with α = 2π·t/period + phase. */
export function circularPosition(c: Vec2, r: number, t: number, period: number, phase: number): Vec2 {
  const a = cycleAngle(t, period, phase);
  return [c[0] + r * Math.cos(a), c[1] + r * Math.sin(a)];
}

export const circularMotionNode = defineNode({
  type: 'circular-motion',
  version: 1,
  label: 'Circular motion',
  category: 'Animation',
  color: '#f2c14e',
  doc: 'A point going round a circle once per period: c + r·(cos α, sin α), α = 2π·t/period + phase.',
  inputs: {
    center: pointInput('centre', 0, 0),
    radius: { type: 'number', label: 'radius', default: 0.5, min: 0, step: 0.01 },
    period: periodInput,
    phase: phaseInput,
    t: timeInput,
  },
  outputs: { point: { type: 'point', label: 'point' } },
  params: { visible: VISIBLE },
  evaluate: ({ inputs }) => {
    const T = inputs.period;
    if (!(T > 0)) return noPeriod(T);
    const p = circularPosition(inputs.center, inputs.radius, inputs.t, T, inputs.phase);
    return { outputs: { point: p } };
  },
  overlay: (ctx, out) => [
    {
      shape: 'circle',
      circle: { c: ctx.inputs.center, r: ctx.inputs.radius } satisfies Circle,
    },
    { shape: 'point', at: out.point },
  ],
  handles: (ctx, out) => [
    { handle: 'center', at: ctx.inputs.center },
    ...(out.point ? [{ handle: 'point', at: out.point }] : []),
  ],
  drag: (handle, to, ctx) => {
    const c = ctx.inputs.center;
    if (handle === 'center') return { center: [...to] };
    // Moving the point sets the radius and the phase that puts it there at the current time.
    const a = Math.atan2(to[1] - c[1], to[0] - c[0]);
    return { radius: dist(c, to), phase: a - cycleAngle(ctx.inputs.t, ctx.inputs.period) };
  },
});
