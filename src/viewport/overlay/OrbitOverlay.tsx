/**
 * The inspected point's orbit drawn over the picture: a ring at the clicked point, a line from
 * each point to the next in the colour of the element applied, and a numbered marker at each step
 * (orbit-path.ts places and clips them). Pointer events pass through to the picture.
 */
import type { JSX } from 'react';
import type { View } from '../../../nodes/core/scene.ts';
import type { Vec2 } from '../../../nodes/core/values.ts';
import { type OrbitStep, placeOrbit } from './orbit-path.ts';

interface Props {
  readonly start: Vec2;
  readonly steps: readonly OrbitStep[];
  readonly view: View;
  readonly width: number;
  readonly height: number;
}

const OUTLINE = 'rgba(8, 10, 16, 0.85)';

export function OrbitOverlay({ start, steps, view, width, height }: Props): JSX.Element {
  const orbit = placeOrbit(start, steps, { view, width, height });
  const [sx, sy] = orbit.start;
  return (
    <svg
      className="kf-orbit"
      width={width}
      height={height}
      viewBox={`0 0 ${width} ${height}`}
      role="img"
      aria-label={`Orbit of the inspected point: ${steps.length} step${steps.length === 1 ? '' : 's'}`}
      data-testid="orbit-overlay"
    >
      {orbit.segments.map(({ a, b, color }, i) => (
        // biome-ignore lint/suspicious/noArrayIndexKey: segments are drawn in path order and never reordered
        <g key={i}>
          <line
            x1={a[0]}
            y1={a[1]}
            x2={b[0]}
            y2={b[1]}
            stroke={OUTLINE}
            strokeWidth={4}
            strokeLinecap="round"
          />
          <line
            x1={a[0]}
            y1={a[1]}
            x2={b[0]}
            y2={b[1]}
            stroke={color}
            strokeWidth={2}
            strokeLinecap="round"
          />
        </g>
      ))}
      <circle cx={sx} cy={sy} r={9} fill="none" stroke={OUTLINE} strokeWidth={4} />
      <circle cx={sx} cy={sy} r={9} fill="none" stroke="#ffffff" strokeWidth={2} />
      <circle cx={sx} cy={sy} r={2} fill="#ffffff" />
      {orbit.markers.map(({ step, at, color }) => (
        <g key={step} className="kf-orbit__marker" data-step={step}>
          <circle cx={at[0]} cy={at[1]} r={8} fill={color} stroke={OUTLINE} strokeWidth={1.5} />
          <text x={at[0]} y={at[1]} dy="0.35em" textAnchor="middle" className="kf-orbit__number">
            {step}
          </text>
        </g>
      ))}
    </svg>
  );
}
