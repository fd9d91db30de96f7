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
import { circleCandidates, type LabelRequest, placeLabels, pointCandidates } from './label-placement.ts';
import { circleRimVisible, clipLineToRect, type ScreenHandle, type ScreenItem } from './screen.ts';
import type { HandleKeyboard } from './use-handle-keyboard.ts';

export const OUTLINE_COLOR = 'rgba(8, 8, 12, 0.78)';
export const LABEL_COLOR = '#f6f6fa';

export interface OverlayShapesProps {
  readonly items: readonly ScreenItem[];
  readonly handles: readonly ScreenHandle[];
  readonly width: number;
  readonly height: number;
  readonly hoveredNodeIds: ReadonlySet<string>;
  readonly hoverHandle: HandleItem | null;
  readonly dragTarget: HandleItem | null;
  readonly showLabels: boolean;
  readonly keyboard?: HandleKnobsProps<HandleItem>['keyboard'];
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

const LABEL_FONT_FAMILY = 'system-ui, sans-serif';
const LABEL_WEIGHT = 600;
/** A label's box height, and where its baseline sits below the box's top (in font sizes). */
const LABEL_HEIGHT_EM = 1.2;
const LABEL_BASELINE_EM = 0.93;

let measureContext: CanvasRenderingContext2D | null | undefined;
/** A label's width as the browser draws it (canvas text metrics in the same font), or an estimate. */
function labelWidth(text: string): number {
  const font = OVERLAY_PX.labelFont;
  if (measureContext === undefined)
    measureContext =
      typeof document === 'undefined' ? null : document.createElement('canvas').getContext('2d');
  if (!measureContext) return 0.7 * font * text.length;
  measureContext.font = `${LABEL_WEIGHT} ${font}px ${LABEL_FONT_FAMILY}`;
  return Math.ceil(measureContext.measureText(text).width);
}

/**
 * The labels to draw (one per node, on its first point or circle) placed so that none overlaps
 * another or leaves the pane (label-placement.ts): the hovered node's first, then points, then
 * circles; the drawn points and handles are kept clear where possible.
 */
function layoutLabels(
  items: readonly ScreenItem[],
  handles: readonly ScreenHandle[],
  width: number,
  height: number,
  hoveredNodeIds: ReadonlySet<string>,
): { key: string; text: string; at: [number, number] }[] {
  const font = OVERLAY_PX.labelFont;
  const requests: (LabelRequest & { text: string })[] = [];
  const seen = new Set<string>();
  items.forEach((item, i) => {
    const s = item.shape;
    if (!item.label || seen.has(item.nodeId) || s.shape === 'line') return;
    seen.add(item.nodeId);
    requests.push({
      id: `${item.nodeId}:${i}`,
      text: item.label,
      width: labelWidth(item.label),
      height: LABEL_HEIGHT_EM * font,
      gap: s.shape === 'point' ? OVERLAY_PX.labelOffset : OVERLAY_PX.labelOffset / 2,
      priority: (hoveredNodeIds.has(item.nodeId) ? 2 : 0) + (s.shape === 'point' ? 1 : 0),
      candidates: s.shape === 'point' ? pointCandidates(s.at) : circleCandidates(s.c, s.r),
    });
  });
  const dot = (at: readonly [number, number], r: number) => ({
    x: at[0] - r,
    y: at[1] - r,
    width: 2 * r,
    height: 2 * r,
  });
  const obstacles = [
    ...items.flatMap((it) =>
      it.shape.shape === 'point' ? [dot(it.shape.at, OVERLAY_PX.pointRadius + 1)] : [],
    ),
    ...handles.map((h) => dot(h.at, OVERLAY_PX.handleRadius + 1)),
  ];
  const placed = placeLabels(requests, { width, height }, obstacles);
  return requests.flatMap((r) => {
    const box = placed.get(r.id);
    return box
      ? [{ key: r.id, text: r.text, at: [box.x, box.y + LABEL_BASELINE_EM * font] as [number, number] }]
      : [];
  });
}

export function OverlayShapes(props: OverlayShapesProps): JSX.Element {
  const { items, handles, width, height, hoveredNodeIds, hoverHandle, dragTarget, showLabels } = props;
  const strokes: JSX.Element[] = [];
  const dots: JSX.Element[] = [];
  items.forEach((item, i) => {
    const hot = hoveredNodeIds.has(item.nodeId);
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
  });
  const labels = showLabels ? layoutLabels(items, handles, width, height, hoveredNodeIds) : [];
  return (
    <>
      <g>{strokes}</g>
      <g>{dots}</g>
      <g
        fontSize={OVERLAY_PX.labelFont}
        fontFamily={LABEL_FONT_FAMILY}
        fontWeight={LABEL_WEIGHT}
        // White on a dark halo reads on any picture; the label sits right next to its shape.
        fill={LABEL_COLOR}
        stroke={OUTLINE_COLOR}
        strokeWidth={3}
        paintOrder="stroke"
        strokeLinejoin="round"
      >
        {labels.map((l) => (
          <text key={`label:${l.key}`} x={l.at[0]} y={l.at[1]} className="kf-overlay-label">
            {l.text}
          </text>
        ))}
      </g>
      <HandleKnobs
        handles={handles}
        hoveredNodeIds={hoveredNodeIds}
        hoverHandle={hoverHandle}
        dragTarget={dragTarget}
        keyboard={props.keyboard}
      />
    </>
  );
}

export interface HandleKnobsProps<T extends HandleRef> {
  readonly handles: readonly { readonly item: T; readonly at: Vec2; readonly color: string }[];
  readonly hoveredNodeIds: ReadonlySet<string>;
  readonly hoverHandle: T | null;
  readonly dragTarget: T | null;
  /** When set, each knob is focusable and takes keys (arrow keys move it): its name and its keys. */
  readonly keyboard?: HandleKeyboard<T>;
}

/** The grab handles (2D and 3D overlays): bigger when hovered, dragged, or their node is hovered. */
export function HandleKnobs<T extends HandleRef>(props: HandleKnobsProps<T>): JSX.Element {
  const { handles, hoveredNodeIds, hoverHandle, dragTarget } = props;
  return (
    <g>
      {handles.map(({ item, at, color }) => {
        const big =
          sameHandle(hoverHandle, item) || sameHandle(dragTarget, item) || hoveredNodeIds.has(item.nodeId);
        const r = big ? OVERLAY_PX.handleRadiusHover : OVERLAY_PX.handleRadius;
        // A knob: the node's colour in a white ring on a dark rim, so it reads on any picture.
        return (
          <g key={`${item.nodeId}/${item.handle}`}>
            <circle cx={at[0]} cy={at[1]} r={r + OVERLAY_PX.outline} fill={OUTLINE_COLOR} />
            {/* biome-ignore lint/a11y/noStaticElementInteractions: role "button" comes with the key handler (both only when `keyboard` is set) */}
            <circle
              data-handle={`${item.nodeId}/${item.handle}`}
              className="kf-overlay-knob"
              tabIndex={props.keyboard ? 0 : undefined}
              role={props.keyboard ? 'button' : undefined}
              aria-roledescription={props.keyboard ? 'movable handle' : undefined}
              aria-label={props.keyboard?.name(item)}
              onKeyDown={props.keyboard && ((e) => props.keyboard?.onKey(item, at, e))}
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
