/**
 * The live render: a canvas driven by the WebGL2 Viewport, pan/zoom on the pane, and the
 * direct-manipulation overlay on top. The view lives in the document but pan/zoom is not an undo
 * step: it is stored with a debounced silent change.
 */
import { useEffect, useRef, useState } from 'react';
import type { Diagnostic } from '../../nodes/core/diagnostics.ts';
import type { View } from '../../nodes/core/scene.ts';
import type { Evaluation } from '../../nodes/graph/evaluate.ts';
import { useEditorState, useStore } from '../state/use-store.ts';
import { type NodePatch, RenderOverlay } from '../viewport/overlay/RenderOverlay.tsx';
import { attachPanZoom } from '../viewport/pan-zoom.ts';
import { Viewport } from '../viewport/viewport.ts';
import { renderHint } from './render-hint.ts';
import { exposeForTests } from './test-hooks.ts';

/** Pan/zoom settles into the document this long after the last wheel tick or drag. */
const VIEW_STORE_DELAY_MS = 300;

export interface RenderInfo {
  readonly samples: number;
  readonly target: number;
  readonly ms: number;
}

interface Props {
  readonly evaluation: Evaluation;
  readonly hoveredNodeId: string | null;
  onHoverNode(id: string | null): void;
  onDiagnostics(d: Diagnostic[]): void;
  onFrame(info: RenderInfo): void;
  /** Gives the app the viewport (for PNG export) once it exists. */
  onViewport(v: Viewport | null): void;
}

export function RenderPane({
  evaluation,
  hoveredNodeId,
  onHoverNode,
  onDiagnostics,
  onFrame,
  onViewport,
}: Props) {
  const store = useStore();
  const doc = useEditorState((s) => s.doc);
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

  // The document's view changes from outside (load, New, example): follow it.
  useEffect(() => setView(doc.view), [doc.view]);

  useEffect(() => {
    try {
      const v = new Viewport(canvas.current!, {
        onDiagnostics: (d) => callbacks.current.onDiagnostics(d),
        onFrame: (info) => callbacks.current.onFrame(info),
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
      viewport.current?.setSize(width, height, window.devicePixelRatio || 1);
    });
    observer.observe(el);
    return () => observer.disconnect();
  }, []);

  useEffect(() => {
    let timer: ReturnType<typeof setTimeout> | undefined;
    const detach = attachPanZoom(
      pane.current!,
      () => viewRef.current,
      (v) => {
        setView(v);
        viewport.current?.setView(v);
        clearTimeout(timer);
        timer = setTimeout(
          () =>
            store.dispatchSilently({
              type: 'set-view',
              view: { center: [v.center[0], v.center[1]], scale: v.scale },
            }),
          VIEW_STORE_DELAY_MS,
        );
      },
    );
    return () => {
      clearTimeout(timer);
      detach();
    };
  }, [store]);

  useEffect(() => {
    const v = viewport.current;
    if (!v) return;
    v.setScene(evaluation.scene);
    v.setView(viewRef.current);
  }, [evaluation]);
  useEffect(() => {
    viewport.current?.setView(view);
  }, [view]);

  const hint = renderHint(doc, evaluation);
  const patchChange = (patches: NodePatch[]) => ({ type: 'set-params' as const, patches });
  return (
    <div className="kf-render" ref={pane} data-testid="render-pane">
      <canvas ref={canvas} className="kf-render__canvas" aria-label="Rendered picture" />
      {size.width > 0 && (
        <RenderOverlay
          doc={doc}
          evaluation={evaluation}
          view={view}
          width={size.width}
          height={size.height}
          hoveredNodeId={hoveredNodeId}
          onHoverNode={onHoverNode}
          onPreview={(patches) => store.preview(patchChange(patches))}
          onCommit={(patches) => store.commit(patchChange(patches), 'drag in the render')}
        />
      )}
      {failure && <div className="kf-render__failure">{failure}</div>}
      {hint && <div className="kf-render__hint">{hint}</div>}
    </div>
  );
}
