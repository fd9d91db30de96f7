/**
 * The sphairahedron parameter-space view in the render pane (paper Fig. 30): the wired
 * Sphairahedron's (zb, zc) plane — the zb axis for prisms and cakes — painted per pixel by what
 * the shape is there (nodes/geometry/space/sphairahedron-space-paint.ts, sharpening while it is
 * computed), the boundaries, axes with labelled ticks, a legend and the current parameter as a red
 * point. A click sets (zb, zc) in one undo step, a drag pans, the wheel zooms (like the 2D view),
 * the arrow keys step the parameter (Shift: larger steps). docs/math-3d.md "The parameter-space view".
 */
import { type KeyboardEvent, useEffect, useMemo, useRef, useState } from 'react';
import type { View } from '../../nodes/core/view.ts';
import { SPACE_CLASSES } from '../../nodes/geometry/space/sphairahedron-space.ts';
import {
  hasZc,
  SpacePainter,
  spaceClassIndex,
  spacePixelParam,
} from '../../nodes/geometry/space/sphairahedron-space-paint.ts';
import {
  SPACE_COLOURS,
  SPACE_NAMES,
  spaceRgba,
  spaceScreen,
  spaceTicks,
  spaceWindow,
} from '../../nodes/geometry/space/sphairahedron-space-picture.ts';
import type { SpaceViewTarget } from '../../nodes/graph/space-view.ts';
import { useStore } from '../state/use-store.ts';
import { attachPanZoom } from '../viewport/pan-zoom.ts';

/** The first view: zb, zc ∈ about [−2.5, 2.5], where every type's space lies. */
const START: View = { center: [0, 0], scale: 5 };
/** A press that moves less than this many pixels is a click (sets the parameter), not a pan. */
const CLICK_SLOP = 4;
/** Milliseconds of painting per animation frame, so the pane stays responsive while it sharpens. */
const SLICE_MS = 12;

const round = (v: number) => Math.round(v * 100) / 100;

export function SpaceView({ target, readOnly = false }: { target: SpaceViewTarget; readOnly?: boolean }) {
  const store = useStore();
  const box = useRef<HTMLDivElement>(null);
  const canvas = useRef<HTMLCanvasElement>(null);
  const [size, setSize] = useState({ width: 0, height: 0 });
  const [view, setView] = useState<View>(START);
  const [done, setDone] = useState(false);
  const viewRef = useRef(view);
  viewRef.current = view;
  const painter = useRef<SpacePainter | null>(null);
  const { type } = target;
  const twoD = hasZc(type);
  const zb = target.zb;
  const zc = twoD ? target.zc : 0;
  const here = SPACE_CLASSES[useMemo(() => spaceClassIndex(type, zb, zc), [type, zb, zc])]!;
  const pointRef = useRef<[number, number]>([zb, zc]);
  pointRef.current = [zb, zc];

  const set = (b: number, c: number) => {
    if (readOnly) return;
    const params = twoD ? { zb: round(b), zc: round(c) } : { zb: round(b) };
    store.dispatch(
      { type: 'set-params', patches: [{ nodeId: target.nodeId, params }] },
      'choose (zb, zc) in the parameter space',
    );
  };
  const setRef = useRef(set);
  setRef.current = set;

  useEffect(() => {
    const el = box.current!;
    const observer = new ResizeObserver(() => setSize({ width: el.clientWidth, height: el.clientHeight }));
    observer.observe(el);
    // The pane under the view orbits the 3D camera: its presses and wheel stay here.
    const stop = (e: Event) => e.stopPropagation();
    const events = ['pointerdown', 'pointermove', 'pointerup', 'wheel'] as const;
    for (const name of events) el.addEventListener(name, stop);
    return () => {
      observer.disconnect();
      for (const name of events) el.removeEventListener(name, stop);
    };
  }, []);

  // Drag pans and the wheel zooms (pan-zoom.ts); a press that does not move is a click.
  useEffect(() => {
    const el = canvas.current!;
    let press: { x: number; y: number; moved: boolean } | null = null;
    const down = (e: PointerEvent) => {
      press = { x: e.clientX, y: e.clientY, moved: false };
    };
    const move = (e: PointerEvent) => {
      if (press && Math.hypot(e.clientX - press.x, e.clientY - press.y) >= CLICK_SLOP) press.moved = true;
    };
    const up = (e: PointerEvent) => {
      const p = press;
      press = null;
      if (!p || p.moved) return;
      const r = el.getBoundingClientRect();
      const [b, c] = spacePixelParam(
        viewRef.current,
        r.width,
        r.height,
        e.clientX - r.left - 0.5,
        e.clientY - r.top - 0.5,
      );
      setRef.current(b, c);
    };
    // Listeners first, so a press is known before pan-zoom moves the view.
    el.addEventListener('pointerdown', down);
    el.addEventListener('pointermove', move);
    el.addEventListener('pointerup', up);
    const detach = attachPanZoom(
      el,
      () => viewRef.current,
      (v) => (!press || press.moved) && setView(v),
    );
    return () => {
      detach();
      el.removeEventListener('pointerdown', down);
      el.removeEventListener('pointermove', move);
      el.removeEventListener('pointerup', up);
    };
  }, []);

  const draw = () => {
    const p = painter.current;
    const ctx = canvas.current?.getContext('2d');
    if (!p || !ctx) return;
    const image = ctx.createImageData(p.width, p.height);
    const options = { point: pointRef.current, zcAxis: twoD };
    spaceRgba(p.classes, p.width, p.height, viewRef.current, options, image.data);
    ctx.putImageData(image, 0, 0);
  };
  const drawRef = useRef(draw);
  drawRef.current = draw;

  // A new picture for every type, view or size, painted a slice per frame.
  useEffect(() => {
    const { width, height } = size;
    if (width <= 0 || height <= 0) return undefined;
    const p = new SpacePainter(type, view, width, height);
    painter.current = p;
    setDone(false);
    let frame = 0;
    const slice = () => {
      const start = performance.now();
      while (!p.done && performance.now() - start < SLICE_MS) p.step(2);
      drawRef.current();
      if (p.done) setDone(true);
      else frame = requestAnimationFrame(slice);
    };
    slice();
    return () => cancelAnimationFrame(frame);
  }, [type, view, size]);
  // The point moves without a new picture.
  // biome-ignore lint/correctness/useExhaustiveDependencies: a new zb or zc is the trigger itself
  useEffect(() => drawRef.current(), [zb, zc]);

  const key = (e: KeyboardEvent<HTMLCanvasElement>) => {
    const step = e.shiftKey ? 0.2 : 0.05;
    const moves: Record<string, [number, number]> = {
      ArrowLeft: [-step, 0],
      ArrowRight: [step, 0],
      ArrowUp: twoD ? [0, step] : [0, 0],
      ArrowDown: twoD ? [0, -step] : [0, 0],
    };
    const m = moves[e.key];
    if (!m || (m[0] === 0 && m[1] === 0)) return;
    e.preventDefault();
    set(zb + m[0], zc + m[1]);
  };

  const { width, height } = size;
  const win = spaceWindow(view, Math.max(width, 1), Math.max(height, 1));
  const [ax, ay] = spaceScreen(view, width, height, 0, 0);
  const labelY = Math.min(Math.max(ay + 16, 14), height - 6);
  const labelX = Math.min(Math.max(ax - 6, 30), width - 4);
  const where = twoD ? `(zb, zc) = (${round(zb)}, ${round(zc)})` : `zb = ${round(zb)}`;
  const name = type.label.split(' · ')[0];
  return (
    <div className="kf-space" ref={box} data-testid="space-view" data-done={done ? 'yes' : 'no'}>
      <canvas
        ref={canvas}
        width={width}
        height={height}
        className="kf-space__canvas"
        tabIndex={0}
        role="slider"
        aria-valuenow={round(zb)}
        aria-valuemin={round(win.zb[0])}
        aria-valuemax={round(win.zb[1])}
        aria-valuetext={`${where}: ${SPACE_NAMES[here]}`}
        aria-label={`Parameter space of ${name}. ${readOnly ? '' : 'Click to choose, drag to pan, wheel to zoom, arrow keys step the parameter (Shift: larger steps)'}`}
        onKeyDown={key}
      />
      <svg className="kf-space__labels" width={width} height={height} aria-hidden="true">
        {spaceTicks(win.zb[0], win.zb[1]).map((t) => (
          <text key={`b${t}`} x={spaceScreen(view, width, height, t, 0)[0]} y={labelY} textAnchor="middle">
            {t}
          </text>
        ))}
        {twoD &&
          spaceTicks(win.zc[0], win.zc[1])
            .filter((t) => t !== 0)
            .map((t) => (
              <text
                key={`c${t}`}
                x={labelX}
                y={spaceScreen(view, width, height, 0, t)[1] + 4}
                textAnchor="end"
              >
                {t}
              </text>
            ))}
        <text x={width - 8} y={labelY - 18} textAnchor="end" className="kf-space__axis">
          zb
        </text>
        {twoD && (
          <text x={labelX + 12} y={16} className="kf-space__axis">
            zc
          </text>
        )}
      </svg>
      <div className="kf-space__panel">
        <p role="status" data-testid="space-view-status">
          {name}: {where} — {SPACE_NAMES[here]}
          {target.wired ? ' (zb or zc is wired: set it at its source)' : ''}
          {done ? '' : ' · drawing…'}
        </p>
        <ul aria-label="Legend">
          {SPACE_CLASSES.map((c) => (
            <li key={c}>
              <span
                aria-hidden="true"
                className="kf-space__swatch"
                style={{ background: SPACE_COLOURS[c] }}
              />
              {SPACE_NAMES[c]}
            </li>
          ))}
        </ul>
      </div>
    </div>
  );
}
