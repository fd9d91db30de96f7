/**
 * Inspect mode of the render pane: a click (in inspect mode) or an Alt-click (any time) on the
 * picture picks a point; it is traced on the CPU and probed on the GPU again once the graph or the
 * view has changed and settled, so the panel always explains the picture on screen. A press that moves is a
 * pan, not a click. Escape closes the panel, then leaves inspect mode. In a 3D view the clicked
 * pixel itself is kept (the camera moves, not the picture's plane) and explained again, by the
 * CPU tracer, as the graph or the camera changes (inspection-3d.ts) — or, for a volume-rendered
 * graph, by the CPU volume renderer (inspection-volume.ts).
 */
import { type RefObject, useEffect, useRef, useState } from 'react';
import type { View } from '../../../nodes/core/scene.ts';
import type { Camera3d, Scene3d } from '../../../nodes/core/scene-3d.ts';
import type { Vec2 } from '../../../nodes/core/values.ts';
import type { Evaluation } from '../../../nodes/graph/evaluate.ts';
import { isTyping } from '../../editor/typing.ts';
import { type Screen, toCss, toWorld } from '../../viewport/overlay/screen.ts';
import type { PixelInspection } from '../../viewport/pixel-probe.ts';
import type { Viewport } from '../../viewport/viewport.ts';
import { type Inspection, inspect } from './inspection.ts';
import { type Inspection3d, inspect3d } from './inspection-3d.ts';
import { type InspectionVolume, inspectVolume } from './inspection-volume.ts';
import { type PanelPlace, panelPlace } from './panel-place.ts';

/** A press that moves less than this (CSS px) before release is a click. */
const CLICK_SLOP = 4;
/** The panel follows edits and pans once they have been still this long (ms). */
const SETTLE_MS = 150;

export interface PixelInspectState {
  /** The inspected world point (the clicked one), or null when the panel is closed. */
  readonly anchor: Vec2 | null;
  readonly inspection: Inspection | Inspection3d | InspectionVolume | null;
  /** Where the panel goes: away from the point (panel-place.ts). */
  readonly place: PanelPlace;
  close(): void;
}

interface Inputs {
  readonly pane: RefObject<HTMLDivElement | null>;
  readonly viewport: RefObject<Viewport | null>;
  readonly evaluation: Evaluation;
  readonly view: View;
  /** A 3D graph's picture and the camera the view shows it through (null: a 2D graph). */
  readonly space: { readonly scene: Scene3d; readonly camera: Camera3d } | null;
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
  const [inspection, setInspection] = useState<Inspection | Inspection3d | InspectionVolume | null>(null);
  /** The clicked CSS point of a 3D view (its explanation follows the camera), or null. */
  const [pixel3d, setPixel3d] = useState<Vec2 | null>(null);
  const latest = useRef(p);
  latest.current = p;
  const anchorRef = useRef(anchor);
  anchorRef.current = anchor;
  const pixel3dRef = useRef(pixel3d);
  pixel3dRef.current = pixel3d;

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
      const { view, width, height, space } = latest.current;
      if (space) setPixel3d(css);
      else setAnchor(toWorld({ view, width, height }, css));
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
      if (anchorRef.current || pixel3dRef.current) {
        setAnchor(null);
        setPixel3d(null);
      } else if (latest.current.mode) latest.current.onModeOff();
    };
    window.addEventListener('keydown', onKey);
    return () => window.removeEventListener('keydown', onKey);
  }, []);

  // Turning inspect mode off closes the panel too.
  const wasMode = useRef(p.mode);
  useEffect(() => {
    if (wasMode.current && !p.mode) {
      setAnchor(null);
      setPixel3d(null);
    }
    wasMode.current = p.mode;
  }, [p.mode]);

  const { evaluation, view, width, height, viewport, space } = p;
  // Switching between a 2D and a 3D graph closes the panel (its point means nothing there).
  const is3d = space !== null;
  useEffect(() => {
    if (is3d) setAnchor(null);
    else setPixel3d(null);
  }, [is3d]);
  const probedAnchor = useRef<Vec2 | null>(null);
  useEffect(() => {
    if (!space || !pixel3d || width === 0 || height === 0) return undefined;
    const { scene, camera } = space;
    const run = () =>
      setInspection(
        scene.volume
          ? inspectVolume(scene, camera, pixel3d, width, height)
          : inspect3d(evaluation, scene, camera, pixel3d, width, height),
      );
    if (probedAnchor.current !== pixel3d) {
      probedAnchor.current = pixel3d;
      run();
      return undefined;
    }
    const timer = setTimeout(run, SETTLE_MS);
    return () => clearTimeout(timer);
  }, [pixel3d, evaluation, space, width, height]);
  useEffect(() => {
    if (space) {
      if (!pixel3d) setInspection(null);
      return undefined;
    }
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
  }, [anchor, evaluation, view, width, height, viewport, space, pixel3d]);

  const css = space ? pixel3d : anchor ? toCss({ view, width, height }, anchor) : null;
  return {
    anchor: space ? null : anchor,
    inspection,
    place: panelPlace(css, width, height),
    close: () => {
      setAnchor(null);
      setPixel3d(null);
    },
  };
}
