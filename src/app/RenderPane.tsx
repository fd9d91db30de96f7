/**
 * The live render: a canvas driven by the WebGL2 Viewport, pan/zoom on the pane, and the
 * direct-manipulation overlay on top. The view lives in the document but pan/zoom is not an undo
 * step: it is stored with a debounced silent change. When the graph's render node is a render-3d
 * node the same canvas and Viewport show the 3D scene instead: orbit/zoom/pan controls, the 3D
 * overlay and "Reset view" take the place of pan/zoom, the 2D overlay and Fit (use-camera-3d.ts).
 */
import { useCallback, useEffect, useMemo, useRef, useState } from 'react';
import type { Diagnostic } from '../../nodes/core/diagnostics.ts';
import type { View } from '../../nodes/core/scene.ts';
import type { Evaluation } from '../../nodes/graph/evaluate.ts';
import { isUnder, type NodePath, pathOf } from '../../nodes/graph/flatten.ts';
import { spaceViewTarget } from '../../nodes/graph/space-view.ts';
import { registry } from '../../nodes/types/index.ts';
import { isTyping } from '../editor/typing.ts';
import { useEditorState, useStore } from '../state/use-store.ts';
import { fitBounds, pictureBounds } from '../viewport/fit-view.ts';
import { liveMedia } from '../viewport/live-media.ts';
import { attachOrbitControls } from '../viewport/orbit-controls.ts';
import { OrbitOverlay } from '../viewport/overlay/OrbitOverlay.tsx';
import { type NodePatch, RenderOverlay } from '../viewport/overlay/RenderOverlay.tsx';
import { LimitSetOverlay3d } from '../viewport/overlay-3d/LimitSetOverlay3d.tsx';
import { RenderOverlay3d } from '../viewport/overlay-3d/RenderOverlay3d.tsx';
import { attachPanZoom } from '../viewport/pan-zoom.ts';
import { Viewport } from '../viewport/viewport.ts';
import { InspectPanel } from './inspect/InspectPanel.tsx';
import { usePixelInspect } from './inspect/use-pixel-inspect.ts';
import { renderHint } from './render-hint.ts';
import { SpaceView } from './SpaceView.tsx';
import { exposeForTests } from './test-hooks.ts';
import { useCamera3d } from './use-camera-3d.ts';
import { useLiveSources } from './use-live-sources.ts';

/** Pan/zoom settles into the document this long after the last wheel tick or drag. */
const VIEW_STORE_DELAY_MS = 300;
const noop = () => {};

export interface RenderInfo {
  readonly samples: number;
  readonly target: number;
  readonly ms: number;
  /** < 1: a 3D preview drawn at reduced resolution while the picture changes. */
  readonly scale?: number;
  /** The share (0–1) of the next full-size 3D sample drawn so far, while it is drawn in bands. */
  readonly band?: number;
}

interface Props {
  readonly evaluation: Evaluation;
  /**
   * The hovered node by its document path (flatten.ts NodePath): a node's construction is drawn
   * highlighted; a group's path highlights everything its inner nodes draw.
   */
  readonly hovered: NodePath | null;
  onHover(path: NodePath | null): void;
  onDiagnostics(d: Diagnostic[]): void;
  onFrame(info: RenderInfo): void;
  /** Gives the app the viewport (for PNG export) once it exists. */
  onViewport(v: Viewport | null): void;
  /** Presenting or embedded: no handles to drag, so nothing here can change the graph. */
  readonly readOnly?: boolean;
  /** Inspect mode (toolbar toggle): a click explains the pixel; handles do not drag. */
  readonly inspecting?: boolean;
  onInspectingOff?(): void;
}

const NONE: ReadonlySet<string> = new Set();

/** What the pane shows when the graph has both a 3D picture and a parameter-space view. */
type PaneShows = '3d' | 'space' | 'both';
/** Side by side only from this pane width (CSS pixels): narrower, the two take turns. */
const BOTH_MIN_WIDTH = 900;
const SHOWS_LABEL: Record<PaneShows, string> = {
  '3d': '3D picture',
  space: 'Parameter space',
  both: 'Side by side',
};

/** The flattened ids of the nodes at or inside `path` (what the overlay draws for it). */
function nodesUnder(evaluation: Evaluation, path: NodePath | null): ReadonlySet<string> {
  if (!path) return NONE;
  const ids = [...evaluation.analysis.nodes.keys()];
  return new Set(ids.filter((id) => isUnder(pathOf(evaluation.origin, id), path)));
}

export function RenderPane({
  evaluation,
  hovered,
  onHover,
  onDiagnostics,
  onFrame,
  onViewport,
  readOnly = false,
  inspecting = false,
  onInspectingOff = noop,
}: Props) {
  const store = useStore();
  const doc = useEditorState((s) => s.doc);
  const time = useEditorState((s) => s.time);
  const pane = useRef<HTMLDivElement>(null);
  const canvas = useRef<HTMLCanvasElement>(null);
  const viewport = useRef<Viewport | null>(null);
  const [size, setSize] = useState({ width: 0, height: 0 });
  const [view, setView] = useState<View>(doc.view);
  const [failure, setFailure] = useState<string | null>(null);
  const viewRef = useRef(view);
  viewRef.current = view;
  const callbacks = useRef({ onDiagnostics, onFrame });
  callbacks.current = { onDiagnostics, onFrame };
  // The app hears the compiler's messages and the live sources' (camera, video) as one list.
  const [compileDiagnostics, setCompileDiagnostics] = useState<Diagnostic[]>([]);
  const live = useLiveSources(evaluation, doc, time);
  useEffect(
    () => callbacks.current.onDiagnostics([...compileDiagnostics, ...live.diagnostics]),
    [compileDiagnostics, live.diagnostics],
  );

  // The document's view changes from outside (load, New, example): follow it.
  useEffect(() => setView(doc.view), [doc.view]);

  useEffect(() => {
    try {
      // A band reports its progress on top of the last frame's numbers; the next frame clears it.
      let last: RenderInfo | null = null;
      const v = new Viewport(canvas.current!, {
        onDiagnostics: setCompileDiagnostics,
        onFrame: (info) => {
          last = info;
          callbacks.current.onFrame(info);
        },
        onBand: ({ rows, of }) => last && callbacks.current.onFrame({ ...last, band: rows / of }),
      });
      viewport.current = v;
      onViewport(v);
      exposeForTests(store, v);
      return () => {
        onViewport(null);
        exposeForTests(store, null);
        viewport.current = null;
        v.dispose();
      };
    } catch (e) {
      setFailure(
        `The live render needs WebGL2, which this browser could not start (${(e as Error).message}).`,
      );
      return undefined;
    }
  }, [onViewport, store]);

  useEffect(() => {
    const el = pane.current!;
    const observer = new ResizeObserver(() => {
      const width = el.clientWidth;
      const height = el.clientHeight;
      setSize({ width, height });
    });
    observer.observe(el);
    return () => observer.disconnect();
  }, []);

  // One way a view changes from inside the pane (pan, zoom, Fit): shown at once, stored in the
  // document a moment later, silently (a view change is not an undo step).
  const storeTimer = useRef<ReturnType<typeof setTimeout> | undefined>(undefined);
  const showView = useCallback(
    (v: View) => {
      setView(v);
      viewport.current?.setView(v);
      clearTimeout(storeTimer.current);
      storeTimer.current = setTimeout(
        () =>
          store.dispatchSilently({
            type: 'set-view',
            view: { center: [v.center[0], v.center[1]], scale: v.scale },
          }),
        VIEW_STORE_DELAY_MS,
      );
    },
    [store],
  );
  useEffect(() => () => clearTimeout(storeTimer.current), []);

  const scene3d = evaluation.scene3d;
  const is3d = scene3d !== null;
  const camera3d = useCamera3d(store, doc, scene3d);
  const { cameraRef, show: showCamera } = camera3d;
  useEffect(
    () =>
      is3d
        ? attachOrbitControls(pane.current!, () => cameraRef.current, showCamera)
        : attachPanZoom(pane.current!, () => viewRef.current, showView),
    [is3d, showView, cameraRef, showCamera],
  );

  const bounds = is3d ? null : pictureBounds(evaluation.scene);
  // F and the corner button: Fit in 2D, back to the render-3d node's camera in 3D.
  const fit = () => (is3d ? camera3d.reset() : bounds && showView(fitBounds(bounds, size)));
  // Pan/zoom listens natively on the pane: a press on the button must not start a pan (React's
  // own stopPropagation runs at the root, after the pane has seen the event).
  const paneButton = useCallback((b: HTMLButtonElement | null) => {
    if (!b) return undefined;
    const stop = (e: PointerEvent) => e.stopPropagation();
    b.addEventListener('pointerdown', stop);
    return () => b.removeEventListener('pointerdown', stop);
  }, []);
  // The same for the view switch's buttons.
  const paneGroup = useCallback((g: HTMLFieldSetElement | null) => {
    if (!g) return undefined;
    const stop = (e: PointerEvent) => e.stopPropagation();
    g.addEventListener('pointerdown', stop);
    return () => g.removeEventListener('pointerdown', stop);
  }, []);
  const fitRef = useRef(fit);
  fitRef.current = fit;
  useEffect(() => {
    const onKey = (e: KeyboardEvent) => {
      if (e.key !== 'f' || e.ctrlKey || e.metaKey || e.altKey || isTyping(e.target)) return;
      e.preventDefault();
      fitRef.current();
    };
    window.addEventListener('keydown', onKey);
    return () => window.removeEventListener('keydown', onKey);
  }, []);

  useEffect(() => {
    const v = viewport.current;
    if (!v) return;
    v.setScene(evaluation.scene3d ?? evaluation.scene);
    v.setView(viewRef.current);
    v.setCamera(cameraRef.current);
  }, [evaluation, cameraRef]);
  useEffect(() => {
    viewport.current?.setView(view);
  }, [view]);
  // The 3D camera is a frame uniform like the view: a move never touches the program.
  useEffect(() => {
    viewport.current?.setCamera(camera3d.camera);
  }, [camera3d.camera]);

  const spaceTarget = useMemo(() => spaceViewTarget(doc), [doc]);
  // The parameter-space view (docs/math-3d.md "The parameter-space view"): alone, or beside the
  // 3D picture when wide, else one of the two by the pane's switch (side by side by default).
  const [chosen, setChosen] = useState<PaneShows | null>(null);
  const wide = size.width >= BOTH_MIN_WIDTH;
  const choices: PaneShows[] = wide ? ['3d', 'space', 'both'] : ['3d', 'space'];
  const shows: PaneShows = !spaceTarget
    ? '3d'
    : !is3d
      ? 'space'
      : chosen && choices.includes(chosen)
        ? chosen
        : wide
          ? 'both'
          : '3d';
  // Side by side, the 3D picture (canvas, overlays, handles, Explain pixel) is the pane's left half,
  // so none of it lies under the parameter-space view on the right.
  const half = shows === 'both';
  const stageWidth = half ? Math.floor(size.width / 2) : size.width;
  const stage = useMemo(() => ({ width: stageWidth, height: size.height }), [stageWidth, size.height]);
  useEffect(() => {
    if (stage.width > 0) viewport.current?.setSize(stage.width, stage.height, window.devicePixelRatio || 1);
  }, [stage]);

  // After the effects that hand the viewport its scene and view: the probe reads what is on screen.
  const space = useMemo(
    () => (scene3d ? { scene: scene3d, camera: camera3d.camera } : null),
    [scene3d, camera3d.camera],
  );
  const inspected = usePixelInspect({
    pane,
    viewport,
    evaluation,
    view,
    space,
    width: stage.width,
    height: stage.height,
    mode: inspecting,
    onModeOff: onInspectingOff,
  });

  // The hints tell an editor what to wire next: nothing for an audience (read-only), where a
  // presentation's early steps have no mirrors yet by design.
  const hint = useMemo(
    () => (readOnly || spaceTarget ? null : renderHint(doc, evaluation, registry)),
    [readOnly, doc, evaluation, spaceTarget],
  );
  const hoveredNodeIds = useMemo(() => nodesUnder(evaluation, hovered), [evaluation, hovered]);
  const onHoverNode = (id: string | null) => onHover(id === null ? null : pathOf(evaluation.origin, id));
  const patchChange = (patches: NodePatch[]) => ({ type: 'set-params' as const, patches });
  return (
    <div
      className={`kf-render${hint ? ' kf-render--idle' : ''}${inspecting ? ' kf-render--inspecting' : ''}`}
      ref={pane}
      data-testid="render-pane"
    >
      <canvas
        ref={canvas}
        className="kf-render__canvas"
        aria-label="Rendered picture"
        style={half ? { width: stage.width } : undefined}
      />
      {size.width > 0 && scene3d && shows !== 'space' && (
        <LimitSetOverlay3d
          scene={scene3d}
          camera={camera3d.camera}
          width={stage.width}
          height={stage.height}
        />
      )}
      {size.width > 0 && scene3d && shows !== 'space' && (
        <RenderOverlay3d
          evaluation={evaluation}
          scene={scene3d}
          camera={camera3d.camera}
          width={stage.width}
          height={stage.height}
          hoveredNodeIds={hoveredNodeIds}
          onHoverNode={onHoverNode}
          onPreview={(patches) => store.preview(patchChange(patches))}
          onCommit={(patches) => store.commit(patchChange(patches), 'drag in the render')}
          readOnly={readOnly}
          inspecting={inspecting}
        />
      )}
      {size.width > 0 && !scene3d && (
        <RenderOverlay
          doc={doc}
          evaluation={evaluation}
          view={view}
          width={size.width}
          height={size.height}
          hoveredNodeIds={hoveredNodeIds}
          onHoverNode={onHoverNode}
          onPreview={(patches) => store.preview(patchChange(patches))}
          onCommit={(patches) => store.commit(patchChange(patches), 'drag in the render')}
          readOnly={readOnly}
          inspecting={inspecting}
        />
      )}
      {inspected.anchor && inspected.inspection && !('kind' in inspected.inspection) && size.width > 0 && (
        <OrbitOverlay
          start={inspected.inspection.trace.start}
          steps={inspected.inspection.word}
          view={view}
          width={size.width}
          height={size.height}
        />
      )}
      {inspected.inspection && (
        <InspectPanel inspection={inspected.inspection} place={inspected.place} onClose={inspected.close} />
      )}
      {(bounds || is3d) && shows !== 'space' && (
        <button
          type="button"
          className={`kf-button kf-render__fit${half ? ' kf-render__fit--half' : ''}`}
          title={is3d ? "Back to the render node's camera (F)" : 'Show the whole picture (F)'}
          ref={paneButton}
          onClick={fit}
        >
          {is3d ? 'Reset view' : 'Fit'}
        </button>
      )}
      {live.cameraWanted && (
        <button
          type="button"
          className="kf-button kf-render__camera"
          title="Draw the camera live (the browser asks once; nothing is recorded or saved)"
          ref={paneButton}
          onClick={() => void liveMedia.startCamera()}
        >
          Start camera
        </button>
      )}
      {spaceTarget && (
        <div className={`kf-render__space kf-render__space--${shows}`} hidden={shows === '3d'}>
          {shows !== '3d' && <SpaceView target={spaceTarget} readOnly={readOnly} />}
        </div>
      )}
      {spaceTarget && is3d && (
        <fieldset className="kf-render__shows" aria-label="The render pane shows" ref={paneGroup}>
          {choices.map((c) => (
            <button
              key={c}
              type="button"
              className="kf-button"
              aria-pressed={shows === c}
              onClick={() => setChosen(c)}
            >
              {SHOWS_LABEL[c]}
            </button>
          ))}
        </fieldset>
      )}
      {failure && <div className="kf-render__failure">{failure}</div>}
      {hint && (
        <div
          className={`kf-render__hint kf-render__hint--${hint.tone}`}
          role="status"
          data-testid="render-hint"
        >
          {hint.text}
        </div>
      )}
    </div>
  );
}
