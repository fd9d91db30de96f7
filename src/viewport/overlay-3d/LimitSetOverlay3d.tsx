/**
 * The quaternion groups' limit sets (Fig. 6) over the live 3D picture: a transparent canvas on
 * which shader-gen/space/limit-dots-3d.ts paints the same depth-sorted, shaded dots as the CPU PNG,
 * at the view's camera (docs/math-3d.md "Quaternion Kleinian groups"). The search runs on the main
 * thread, so it waits until the camera has rested for a moment; until then the last dots stay.
 * Not interactive: pointer events pass through to the orbit controls and the handles.
 */
import { type JSX, useEffect, useRef, useState } from 'react';
import type { Camera3d, Scene3d } from '../../../nodes/core/scene-3d.ts';
import { limitDots3d, paintLimitDots3d } from '../../../shader-gen/space/limit-dots-3d.ts';

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
  useEffect(() => {
    const c = canvas.current;
    if (!c || !sets?.length || width <= 0 || height <= 0) return undefined;
    const timer = setTimeout(() => {
      const w = Math.round(width);
      const h = Math.round(height);
      const seen = { ...scene, camera };
      const { dots, notes: found } = limitDots3d(seen, w, h);
      const image = new ImageData(w, h);
      paintLimitDots3d(seen, dots, w, h, image.data);
      c.width = w;
      c.height = h;
      c.getContext('2d')?.putImageData(image, 0, 0);
      setNotes(found.map((n) => n.text));
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
