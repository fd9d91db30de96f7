/**
 * What a Shift-drag snapped to, drawn while it lasts: the grid, the angle ray with its degrees, the
 * circle the rim touches, or the rounded radius. Faint and dashed so the picture stays readable.
 */
import type { JSX } from 'react';
import type { Vec2 } from '../../../nodes/core/values.ts';
import { fmt } from '../../../nodes/types/shared.ts';
import { OVERLAY_PX } from './constants.ts';
import { LABEL_COLOR, OUTLINE_COLOR } from './OverlayShapes.tsx';
import { clipLineToRect, pxPerWorld, type Screen, toCss, toWorld } from './screen.ts';
import type { SnapGuide } from './snap-rules.ts';

const GUIDE = LABEL_COLOR;

function GridLines({ screen, step }: { screen: Screen; step: number }): JSX.Element {
  const [x0, y1] = toWorld(screen, [0, 0]);
  const [x1, y0] = toWorld(screen, [screen.width, screen.height]);
  const xs: number[] = [];
  const ys: number[] = [];
  for (let k = Math.ceil(x0 / step); k * step <= x1; k++) xs.push(toCss(screen, [k * step, 0])[0]);
  for (let k = Math.ceil(y0 / step); k * step <= y1; k++) ys.push(toCss(screen, [0, k * step])[1]);
  const d = [...xs.map((x) => `M${x},0V${screen.height}`), ...ys.map((y) => `M0,${y}H${screen.width}`)].join(
    '',
  );
  return <path d={d} stroke={GUIDE} strokeWidth={1} opacity={0.22} fill="none" />;
}

function Caption({ at, text }: { at: Vec2; text: string }): JSX.Element {
  return (
    <text
      x={at[0] + OVERLAY_PX.labelOffset}
      y={at[1] + 2 * OVERLAY_PX.labelOffset}
      fill={GUIDE}
      stroke={OUTLINE_COLOR}
      strokeWidth={3}
      paintOrder="stroke"
      fontSize={11}
      fontFamily="system-ui, sans-serif"
    >
      {text}
    </text>
  );
}

export function SnapGuides({
  screen,
  guide,
  at,
}: {
  screen: Screen;
  guide: SnapGuide;
  at: Vec2;
}): JSX.Element {
  const p = toCss(screen, at);
  const dash = { stroke: GUIDE, strokeWidth: 1, strokeDasharray: '4 4', fill: 'none' };
  switch (guide.kind) {
    case 'grid':
      return (
        <g data-snap="grid">
          <GridLines screen={screen} step={guide.step} />
        </g>
      );
    case 'angle': {
      const pivot = toCss(screen, guide.pivot);
      const seg = clipLineToRect(pivot, p, screen.width, screen.height, 0);
      // The line it meets at π/n, drawn as a guide too, so the user sees which one.
      const ref = guide.piOver?.line;
      const other = ref
        ? clipLineToRect(toCss(screen, ref.a), toCss(screen, ref.b), screen.width, screen.height, 0)
        : null;
      return (
        <g data-snap="angle">
          {seg && <path d={`M${seg[0][0]},${seg[0][1]}L${seg[1][0]},${seg[1][1]}`} {...dash} />}
          {other && <path d={`M${other[0][0]},${other[0][1]}L${other[1][0]},${other[1][1]}`} {...dash} />}
          <Caption at={pivot} text={guide.piOver ? `π/${guide.piOver.n}` : `${guide.degrees}°`} />
        </g>
      );
    }
    case 'tangent': {
      const c = toCss(screen, guide.touching.c);
      return (
        <g data-snap="tangent">
          <circle cx={c[0]} cy={c[1]} r={guide.touching.r * pxPerWorld(screen)} {...dash} strokeWidth={2} />
          <circle cx={p[0]} cy={p[1]} r={OVERLAY_PX.handleRadiusHover + 3} {...dash} />
          <Caption at={p} text="tangent" />
        </g>
      );
    }
    case 'radius': {
      const c = toCss(screen, guide.center);
      return (
        <g data-snap="radius">
          <path d={`M${c[0]},${c[1]}L${p[0]},${p[1]}`} {...dash} />
          <Caption at={p} text={`r = ${fmt(guide.radius)}`} />
        </g>
      );
    }
  }
}
