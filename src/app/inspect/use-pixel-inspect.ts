/**
 * Inspect mode of the render pane: a click (in inspect mode) or an Alt-click (any time) on the
 * picture picks a point; it is traced on the CPU and probed on the GPU again once the graph or the
 * view has changed and settled, so the panel always explains the picture on screen. A press that moves is a
 * pan, not a click. Escape closes the panel, then leaves inspect mode.
 */
import { type RefObject, useEffect, useRef, useState } from 'react';
import type { View } from '../../../nodes/core/scene.ts';
import type { Vec2 } from '../../../nodes/core/values.ts';
import type { Evaluation } from '../../../nodes/graph/evaluate.ts';
import { isTyping } from '../../editor/typing.ts';
import { type Screen, toCss, toWorld } from '../../viewport/overlay/screen.ts';
import type { PixelInspection } from '../../viewport/pixel-probe.ts';
import type { Viewport } from '../../viewport/viewport.ts';
import { type Inspection, inspect } from './inspection.ts';

/** A press that moves less than this (CSS px) before release is a click. */
const CLICK_SLOP = 4;
/** The panel follows edits and pans once they have been still this long (ms). */
const SETTLE_MS = 150;

export interface PixelInspectState {
  /** The inspected world point (the clicked one), or null when the panel is closed. */
  readonly anchor: Vec2 | null;
  readonly inspection: Inspection | null;
  /** The panel docks on the side away from the point. */
  readonly side: 'left' | 'right';
  close(): void;
}

interface Inputs {
  readonly pane: RefObject<HTMLDivElement | null>;
  readonly viewport: RefObject<Viewport | null>;
  readonly evaluation: Evaluation;
  readonly view: View;
  readonly width: number;
  readonly height: number;
  /** Inspect mode (the toolbar toggle): a plain click inspects and handles do not drag. */
  readonly mode: boolean;
  onModeOff(): void;
}

/** The probe at the anchor: the GPU's pixel there, or (point off screen) the CPU alone. */
function probeAt(viewport: Viewport | null, screen: Screen, anchor: Vec2): PixelInspection | null {
  const css = toCss(screen, anchor);
  const onScreen = css[0] >= 0 && css[0] < screen.width && css[1] >= 0 && css[1] < screen.height;
  if (viewport && onScreen) return viewport.inspectAt(css[0], css[1]);
  const reason = viewport ? 'the point is outside the view' : 'the live render is not running';
  return { pixel: { px: -1, py: -1, width: 0, height: 0 }, world: anchor, gpu: { ok: false, reason } };
}

export function usePixelInspect(p: Inputs): PixelInspectState {
  const [anchor, setAnchor] = useState<Vec2 | null>(null);
  const [inspection, setInspection] = useState<Inspection | null>(null);
  const latest = useRef(p);
  latest.current = p;
  const anchorRef = useRef(anchor);
  anchorRef.current = anchor;

  useEffect(() => {
    const el = p.pane.current;
    if (!el) return undefined;
    let press: { id: number; x: number; y: number; alt: boolean } | null = null;
    const local = (e: PointerEvent): Vec2 => {
      const r = el.getBoundingClientRect();
      return [e.clientX - r.left, e.clientY - r.top];
    };
    const onDown = (e: PointerEvent) => {
      press = null;
      if (!e.isPrimary || e.button !== 0) return;
      // The panel, the Fit button and other controls in the pane are not the picture.
      if ((e.target as Element).closest('button, .kf-inspect, input, a')) return;
      const [x, y] = local(e);
      press = { id: e.pointerId, x, y, alt: e.altKey };
    };
    const onUp = (e: PointerEvent) => {
      const start = press;
      press = null;
      if (!start || e.pointerId !== start.id || !(latest.current.mode || start.alt)) return;
      const css = local(e);
      if (Math.hypot(css[0] - start.x, css[1] - start.y) > CLICK_SLOP) return;
      const { view, width, height } = latest.current;
      setAnchor(toWorld({ view, width, height }, css));
    };
    el.addEventListener('pointerdown', onDown);
    el.addEventListener('pointerup', onUp);
    return () => {
      el.removeEventListener('pointerdown', onDown);
      el.removeEventListener('pointerup', onUp);
    };
  }, [p.pane]);

  // Escape: close the panel first, then leave inspect mode.
  useEffect(() => {
    const onKey = (e: KeyboardEvent) => {
      if (e.key !== 'Escape' || e.defaultPrevented || isTyping(e.target)) return;
      if (anchorRef.current) setAnchor(null);
      else if (latest.current.mode) latest.current.onModeOff();
    };
    window.addEventListener('keydown', onKey);
    return () => window.removeEventListener('keydown', onKey);
  }, []);

  // Turning inspect mode off closes the panel too.
  const wasMode = useRef(p.mode);
  useEffect(() => {
    if (wasMode.current && !p.mode) setAnchor(null);
    wasMode.current = p.mode;
  }, [p.mode]);

  const { evaluation, view, width, height, viewport } = p;
  const probedAnchor = useRef<Vec2 | null>(null);
  useEffect(() => {
    if (!anchor || width === 0 || height === 0) {
      probedAnchor.current = null;
      setInspection(null);
      return undefined;
    }
    const run = () => {
      probedAnchor.current = anchor;
      const probe = probeAt(viewport.current, { view, width, height }, anchor);
      setInspection(probe ? inspect(evaluation, probe) : null);
    };
    // A new point is answered at once. While the graph or the view keeps changing (a drag, a pan)
    // the GPU read-back — a pipeline stall — waits until they have been still for a moment, so it
    // never runs once per frame of a gesture.
    if (probedAnchor.current !== anchor) {
      run();
      return undefined;
    }
    const timer = setTimeout(run, SETTLE_MS);
    return () => clearTimeout(timer);
  }, [anchor, evaluation, view, width, height, viewport]);

  const css = anchor ? toCss({ view, width, height }, anchor) : null;
  return {
    anchor,
    inspection,
    side: css && css[0] > width / 2 ? 'left' : 'right',
    close: () => setAnchor(null),
  };
}
