/**
 * The construction drawn in SVG over the render: each shape in its node's colour on a dark
 * outline (so it reads on any picture), with constant pixel widths at every zoom, labels, and the
 * grab handles on top. The hovered node's geometry is drawn wider with a soft halo.
 */
import type { JSX } from 'react';
import type { HandleItem } from '../../../nodes/core/scene.ts';
import type { Vec2 } from '../../../nodes/core/values.ts';
import type { HandleRef } from '../../../nodes/graph/drag-patches.ts';
import { OVERLAY_PX } from './constants.ts';
import { circleRimVisible, clipLineToRect, type ScreenHandle, type ScreenItem } from './screen.ts';

export const OUTLINE_COLOR = 'rgba(8, 8, 12, 0.78)';
export const LABEL_COLOR = '#f6f6fa';

export interface OverlayShapesProps {
  readonly items: readonly ScreenItem[];
  readonly handles: readonly ScreenHandle[];
  readonly width: number;
  readonly height: number;
  readonly hoveredNodeId: string | null;
  readonly hoverHandle: HandleItem | null;
  readonly dragTarget: HandleItem | null;
  readonly showLabels: boolean;
}

const sameHandle = (a: HandleRef | null, b: HandleRef) => a?.nodeId === b.nodeId && a.handle === b.handle;

/** An SVG path for a stroked shape (line clipped to the pane, circle), or null when off screen. */
function strokePath(item: ScreenItem, width: number, height: number): string | null {
  const s = item.shape;
  if (s.shape === 'line') {
    const seg = clipLineToRect(s.a, s.b, width, height, OVERLAY_PX.lineMargin);
    return seg ? `M${seg[0][0]},${seg[0][1]}L${seg[1][0]},${seg[1][1]}` : null;
  }
  if (s.shape !== 'circle' || !circleRimVisible(s.c, s.r, width, height, OVERLAY_PX.lineMargin)) return null;
  const far = 1000 * Math.max(width, height, 1);
  if (s.r > far) {
    // A huge circle is a line on screen (sagitta < 1 px): its tangent at the rim point nearest the
    // pane's centre. SVG arcs with radii of millions of pixels lose precision.
    const dx = width / 2 - s.c[0];
    const dy = height / 2 - s.c[1];
    const l = Math.hypot(dx, dy);
    const q: [number, number] = [s.c[0] + (s.r * dx) / l, s.c[1] + (s.r * dy) / l];
    const seg = clipLineToRect(q, [q[0] - dy, q[1] + dx], width, height, OVERLAY_PX.lineMargin);
    return seg ? `M${seg[0][0]},${seg[0][1]}L${seg[1][0]},${seg[1][1]}` : null;
  }
  const [cx, cy] = s.c;
  return `M${cx - s.r},${cy}a${s.r},${s.r} 0 1,0 ${2 * s.r},0a${s.r},${s.r} 0 1,0 ${-2 * s.r},0`;
}

/** Where a label goes: up-right of a point, at the rim's upper-right (45°) for a circle. */
function labelAnchor(item: ScreenItem): [number, number] | null {
  const s = item.shape;
  const o = OVERLAY_PX.labelOffset;
  if (s.shape === 'point') return [s.at[0] + o, s.at[1] - o];
  if (s.shape === 'circle') return [s.c[0] + s.r * Math.SQRT1_2 + o / 2, s.c[1] - s.r * Math.SQRT1_2 - o / 2];
  return null;
}

/**
 * Keeps a label whose anchor is on the pane fully inside it (a point near the right edge gets its
 * label pulled left); a label whose anchor is off the pane is not drawn. Width is estimated from
 * the character count (about 0.62 em per character).
 */
function placeLabel(
  anchor: [number, number],
  text: string,
  width: number,
  height: number,
): [number, number] | null {
  const font = OVERLAY_PX.labelFont;
  const textWidth = 0.62 * font * text.length;
  const [x, y] = anchor;
  if (x < -textWidth || x > width || y < 0 || y > height + font) return null;
  const pad = 4;
  return [
    Math.max(pad, Math.min(x, width - pad - textWidth)),
    Math.max(font + pad, Math.min(y, height - pad)),
  ];
}

export function OverlayShapes(props: OverlayShapesProps): JSX.Element {
  const { items, handles, width, height, hoveredNodeId, hoverHandle, dragTarget, showLabels } = props;
  const strokes: JSX.Element[] = [];
  const dots: JSX.Element[] = [];
  const labels: JSX.Element[] = [];
  const labelled = new Set<string>();
  items.forEach((item, i) => {
    const hot = item.nodeId === hoveredNodeId;
    const w = hot ? OVERLAY_PX.strokeHover : OVERLAY_PX.stroke;
    const key = `${item.nodeId}:${i}`;
    if (item.shape.shape === 'point') {
      const [x, y] = item.shape.at;
      if (x < -OVERLAY_PX.lineMargin || y < -OVERLAY_PX.lineMargin) return;
      if (x > width + OVERLAY_PX.lineMargin || y > height + OVERLAY_PX.lineMargin) return;
      const r = OVERLAY_PX.pointRadius + (hot ? 1.5 : 0);
      dots.push(
        <g key={key} data-node={item.nodeId} data-shape="point">
          {hot && <circle cx={x} cy={y} r={r + 4} fill={item.color} opacity={0.3} />}
          <circle
            cx={x}
            cy={y}
            r={r}
            fill={item.color}
            stroke={OUTLINE_COLOR}
            strokeWidth={OVERLAY_PX.outline}
          />
        </g>,
      );
    } else {
      const d = strokePath(item, width, height);
      if (!d) return;
      strokes.push(
        <g key={key} data-node={item.nodeId} data-shape={item.shape.shape} fill="none">
          {hot && <path d={d} stroke={item.color} strokeWidth={w + 8} opacity={0.25} />}
          <path d={d} stroke={OUTLINE_COLOR} strokeWidth={w + 2 * OVERLAY_PX.outline} />
          <path d={d} stroke={item.color} strokeWidth={w} />
        </g>,
      );
    }
    const anchor = showLabels && item.label && !labelled.has(item.nodeId) ? labelAnchor(item) : null;
    const at = anchor && item.label ? placeLabel(anchor, item.label, width, height) : null;
    if (at) {
      labelled.add(item.nodeId);
      labels.push(
        <text key={`label:${key}`} x={at[0]} y={at[1]} className="kf-overlay-label">
          {item.label}
        </text>,
      );
    }
  });
  return (
    <>
      <g>{strokes}</g>
      <g>{dots}</g>
      <g
        fontSize={OVERLAY_PX.labelFont}
        fontFamily="system-ui, sans-serif"
        fontWeight={600}
        // White on a dark halo reads on any picture; the label sits right next to its shape.
        fill={LABEL_COLOR}
        stroke={OUTLINE_COLOR}
        strokeWidth={3}
        paintOrder="stroke"
        strokeLinejoin="round"
      >
        {labels}
      </g>
      <HandleKnobs
        handles={handles}
        hoveredNodeId={hoveredNodeId}
        hoverHandle={hoverHandle}
        dragTarget={dragTarget}
      />
    </>
  );
}

export interface HandleKnobsProps<T extends HandleRef> {
  readonly handles: readonly { readonly item: T; readonly at: Vec2; readonly color: string }[];
  readonly hoveredNodeId: string | null;
  readonly hoverHandle: T | null;
  readonly dragTarget: T | null;
}

/** The grab handles (2D and 3D overlays): bigger when hovered, dragged, or their node is hovered. */
export function HandleKnobs<T extends HandleRef>(props: HandleKnobsProps<T>): JSX.Element {
  const { handles, hoveredNodeId, hoverHandle, dragTarget } = props;
  return (
    <g>
      {handles.map(({ item, at, color }) => {
        const big =
          sameHandle(hoverHandle, item) || sameHandle(dragTarget, item) || item.nodeId === hoveredNodeId;
        const r = big ? OVERLAY_PX.handleRadiusHover : OVERLAY_PX.handleRadius;
        // A knob: the node's colour in a white ring on a dark rim, so it reads on any picture.
        return (
          <g key={`${item.nodeId}/${item.handle}`}>
            <circle cx={at[0]} cy={at[1]} r={r + OVERLAY_PX.outline} fill={OUTLINE_COLOR} />
            <circle
              data-handle={`${item.nodeId}/${item.handle}`}
              cx={at[0]}
              cy={at[1]}
              r={r}
              fill={color}
              stroke="#ffffff"
              strokeWidth={1.5}
            />
          </g>
        );
      })}
    </g>
  );
}
