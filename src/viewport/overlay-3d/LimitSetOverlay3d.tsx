/**
 * The quaternion groups' limit sets (Fig. 6) over the live 3D picture: a transparent canvas on
 * which shader-gen/space/limit-dots-3d.ts paints the same depth-sorted, shaded dots as the CPU PNG,
 * at the view's camera (docs/math-3d.md "Quaternion Kleinian groups"). The search runs in a worker
 * (./limit-set-worker.ts) once the camera has rested for a moment; until its dots arrive the last
 * ones stay, and a search made stale by a newer view is stopped (the worker is replaced). Where no
 * worker starts, the same code runs here. Not interactive: pointer events pass through to the
 * orbit controls and the handles.
 */
import { type JSX, useEffect, useRef, useState } from 'react';
import type { Camera3d, Scene3d } from '../../../nodes/core/scene-3d.ts';
import { type LimitSetJob, type LimitSetResult, paintLimitSetJob } from './limit-set-worker.ts';

/** How long the camera must rest before the limit set is searched again. */
const REST_MS = 150;

export function LimitSetOverlay3d(props: {
  scene: Scene3d;
  camera: Camera3d;
  width: number;
  height: number;
}): JSX.Element | null {
  const { scene, camera, width, height } = props;
  const canvas = useRef<HTMLCanvasElement>(null);
  const [notes, setNotes] = useState<readonly string[]>([]);
  const sets = scene.limitSets;
  // One worker, replaced when a search in flight is made stale; ended with the overlay.
  const worker = useRef<{ worker: Worker; busy: boolean } | null>(null);
  const latest = useRef(0);
  useEffect(() => () => worker.current?.worker.terminate(), []);
  useEffect(() => {
    const c = canvas.current;
    if (!c || !sets?.length || width <= 0 || height <= 0) return undefined;
    // `where`: "worker" or "here" (data-search on the canvas, which the e2e test reads).
    const show = (r: LimitSetResult, where: 'worker' | 'here') => {
      if (r.id !== latest.current) return;
      c.dataset.search = where;
      c.width = r.width;
      c.height = r.height;
      c.getContext('2d')?.putImageData(new ImageData(r.pixels, r.width, r.height), 0, 0);
      setNotes(r.notes);
    };
    const timer = setTimeout(() => {
      const job: LimitSetJob = {
        id: ++latest.current,
        scene: { ...scene, camera },
        width: Math.round(width),
        height: Math.round(height),
      };
      const w = searchWorker(worker, show);
      if (!w) return show(paintLimitSetJob(job), 'here');
      // A worker that fails to load or throws: this view is searched here, the next gets a new one.
      w.worker.onerror = () => {
        w.worker.terminate();
        if (worker.current === w) worker.current = null;
        show(paintLimitSetJob(job), 'here');
      };
      try {
        w.busy = true;
        w.worker.postMessage(job);
      } catch {
        // A scene the worker cannot receive (not structured-cloneable): search here instead.
        w.busy = false;
        show(paintLimitSetJob(job), 'here');
      }
    }, REST_MS);
    return () => clearTimeout(timer);
  }, [scene, sets, camera, width, height]);
  if (!sets?.length) return null;
  return (
    <>
      <canvas
        ref={canvas}
        data-testid="limit-set-overlay"
        aria-label="Limit set of the quaternion Kleinian group"
        style={{ position: 'absolute', inset: 0, width, height, pointerEvents: 'none' }}
      />
      {/* A live status: a screen reader hears that the search stopped short (the dots alone say nothing). */}
      <div role="status" data-testid="limit-set-status">
        {notes.map((n, i) => (
          <div
            key={n}
            data-testid="limit-set-note"
            style={{
              position: 'absolute',
              left: 8,
              bottom: 10 + 18 * i,
              color: '#ffcc66',
              font: '12px system-ui, sans-serif',
              textShadow: '0 0 3px #000',
              pointerEvents: 'none',
            }}
          >
            Limit set: {n}
          </div>
        ))}
      </div>
    </>
  );
}

/**
 * The overlay's worker, started on first use; one still searching for an older view is terminated
 * and replaced (a search cannot be interrupted otherwise). Null where workers cannot start.
 */
function searchWorker(
  ref: { current: { worker: Worker; busy: boolean } | null },
  show: (r: LimitSetResult, where: 'worker') => void,
): { worker: Worker; busy: boolean } | null {
  if (ref.current?.busy) {
    ref.current.worker.terminate();
    ref.current = null;
  }
  if (!ref.current) {
    try {
      const worker = new Worker(new URL('./limit-set-worker.ts', import.meta.url), { type: 'module' });
      ref.current = { worker, busy: false };
    } catch {
      return null;
    }
  }
  const entry = ref.current;
  entry.worker.onmessage = (e: MessageEvent<LimitSetResult>) => {
    entry.busy = false;
    show(e.data, 'worker');
  };
  return entry;
}
