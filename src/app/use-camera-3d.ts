/**
 * The 3D view's camera as view state, the twin of the 2D view in RenderPane: orbiting, zooming and
 * panning show at once and are stored in the document a moment later, silently (`camera3d`, not an
 * undo step), so a document reopens with the camera it was saved with. Absent, the view shows the
 * render-3d node's own camera, which "Reset view" goes back to; editing that camera on the node
 * also brings the view to it.
 */
import { useCallback, useEffect, useRef, useState } from 'react';
import { sameCamera3d } from '../../nodes/core/camera-3d.ts';
import { type Camera3d, DEFAULT_CAMERA_3D, type Scene3d } from '../../nodes/core/scene-3d.ts';
import type { GraphDoc } from '../../nodes/graph/document.ts';
import type { EditorStore } from '../state/store.ts';

/** A camera move settles into the document this long after the last one (as the 2D view does). */
const CAMERA_STORE_DELAY_MS = 300;

/** The document's form of a camera: plain mutable arrays (documents are JSON). */
const stored = (c: Camera3d): NonNullable<GraphDoc['camera3d']> => ({
  position: [c.position[0], c.position[1], c.position[2]],
  target: [c.target[0], c.target[1], c.target[2]],
  fovDeg: c.fovDeg,
});

export interface Camera3dState {
  /** The camera the 3D view shows now. */
  readonly camera: Camera3d;
  readonly cameraRef: { readonly current: Camera3d };
  /** Shows `c` now and stores it in the document a moment later. */
  show(c: Camera3d): void;
  /** Back to the render-3d node's camera (the stored view camera is dropped). */
  reset(): void;
}

export function useCamera3d(store: EditorStore, doc: GraphDoc, scene3d: Scene3d | null): Camera3dState {
  const home = scene3d?.camera ?? DEFAULT_CAMERA_3D;
  const [camera, setCamera] = useState<Camera3d>(doc.camera3d ?? home);
  const cameraRef = useRef(camera);
  cameraRef.current = camera;
  const timer = useRef<ReturnType<typeof setTimeout> | undefined>(undefined);
  useEffect(() => () => clearTimeout(timer.current), []);

  // What the view follows from outside: the document's camera (load, example, undo of an open) or,
  // without one, the node's. A new camera ON THE SAME render-3d node while the document's camera
  // stayed put is an edit of the node's camera: the view goes to it and forgets its own.
  const seen = useRef({ home, nodeId: scene3d?.renderNodeId ?? null, docCamera: doc.camera3d });
  const nodeId = scene3d?.renderNodeId ?? null;
  useEffect(() => {
    const before = seen.current;
    seen.current = { home, nodeId, docCamera: doc.camera3d };
    const nodeCameraEdited =
      before.nodeId === nodeId && !sameCamera3d(before.home, home) && before.docCamera === doc.camera3d;
    if (nodeCameraEdited && doc.camera3d) {
      clearTimeout(timer.current);
      store.dispatchSilently({ type: 'set-camera-3d', camera: null });
      setCamera(home);
      return;
    }
    const next = doc.camera3d ?? home;
    // A camera from outside wins: a store still pending from the last orbit must not overwrite it.
    if (!sameCamera3d(cameraRef.current, next)) clearTimeout(timer.current);
    setCamera((old) => (sameCamera3d(old, next) ? old : next));
  }, [store, doc.camera3d, home, nodeId]);

  const show = useCallback(
    (c: Camera3d) => {
      setCamera(c);
      cameraRef.current = c;
      clearTimeout(timer.current);
      timer.current = setTimeout(
        () => store.dispatchSilently({ type: 'set-camera-3d', camera: stored(c) }),
        CAMERA_STORE_DELAY_MS,
      );
    },
    [store],
  );

  const reset = useCallback(() => {
    clearTimeout(timer.current);
    setCamera(home);
    cameraRef.current = home;
    store.dispatchSilently({ type: 'set-camera-3d', camera: null });
  }, [store, home]);

  return { camera, cameraRef, show, reset };
}
