/**
 * Framing the picture in a pane of any shape. A view's `scale` is the world height of the pane
 * (docs/math.md "Plane, view"), so a picture framed for a square pane is cropped left and right in a
 * pane taller than wide; these functions make the whole picture fit in both dimensions.
 */
import type { Scene, View } from '../../nodes/core/scene.ts';
import type { Vec2 } from '../../nodes/core/values.ts';

export interface Bounds {
  readonly min: Vec2;
  readonly max: Vec2;
}

export interface PaneSize {
  readonly width: number;
  readonly height: number;
}

/** Room left around a fitted picture: 4 % on each side. */
const MARGIN = 1.08;

/**
 * The view whose pane shows `bounds` whole, centred: the world height is the larger of the box's
 * height and its width × H/W (the width it needs at this aspect ratio), times the margin.
 */
export function fitBounds(bounds: Bounds, pane: PaneSize): View {
  const w = Math.max(bounds.max[0] - bounds.min[0], 1e-9);
  const h = Math.max(bounds.max[1] - bounds.min[1], 1e-9);
  const aspect = pane.width > 0 && pane.height > 0 ? pane.height / pane.width : 1;
  return {
    center: [(bounds.min[0] + bounds.max[0]) / 2, (bounds.min[1] + bounds.max[1]) / 2],
    scale: Math.max(h, w * aspect) * MARGIN,
  };
}

/**
 * A saved view framed for a square pane (the square of side `scale` around its centre), shown in
 * this pane: unchanged when the pane is at least as wide as tall, otherwise zoomed out until the
 * square's width fits (scale · H/W).
 */
export function fitSquareView(view: View, pane: PaneSize): View {
  if (!(pane.width > 0 && pane.height > 0) || pane.width >= pane.height) return view;
  return { center: view.center, scale: (view.scale * pane.height) / pane.width };
}

/**
 * The view an example opens with: its saved view (fitSquareView) when that shows the whole
 * picture (`bounds`, what Fit frames), otherwise Fit's view — an example must not open cropped
 * and need a Fit (the Apollonian gasket's mirror circles reach past its saved square).
 */
export function openingView(view: View, bounds: Bounds | null, pane: PaneSize): View {
  const shown = fitSquareView(view, pane);
  if (!bounds || !(pane.width > 0 && pane.height > 0)) return shown;
  const halfH = shown.scale / 2;
  const halfW = (halfH * pane.width) / pane.height;
  const [cx, cy] = shown.center;
  const inside =
    bounds.min[0] >= cx - halfW &&
    bounds.max[0] <= cx + halfW &&
    bounds.min[1] >= cy - halfH &&
    bounds.max[1] <= cy + halfH;
  return inside ? shown : fitBounds(bounds, pane);
}

/**
 * What "the picture" is, for Fit: the render's clip disk when it has one (everything outside is
 * background); otherwise the construction — the circles and points drawn over the render and the
 * circle mirrors. Lines are infinite and count only by the points that define them. Null when the
 * scene shows nothing to frame.
 */
export function pictureBounds(scene: Scene): Bounds | null {
  const box = {
    min: [Infinity, Infinity] as [number, number],
    max: [-Infinity, -Infinity] as [number, number],
  };
  const add = (x: number, y: number, r = 0) => {
    if (!Number.isFinite(x) || !Number.isFinite(y) || !Number.isFinite(r)) return;
    box.min[0] = Math.min(box.min[0], x - r);
    box.min[1] = Math.min(box.min[1], y - r);
    box.max[0] = Math.max(box.max[0], x + r);
    box.max[1] = Math.max(box.max[1], y + r);
  };
  if (scene.clip) add(scene.clip.c[0], scene.clip.c[1], scene.clip.r);
  else {
    for (const { shape: s } of scene.overlays) {
      if (s.shape === 'point') add(s.at[0], s.at[1]);
      else if (s.shape === 'circle') add(s.circle.c[0], s.circle.c[1], s.circle.r);
      else {
        add(s.line.a[0], s.line.a[1]);
        add(s.line.b[0], s.line.b[1]);
      }
    }
    for (const e of scene.elements) if (e.kind === 'inversion') add(e.c[0], e.c[1], e.r);
  }
  return box.min[0] <= box.max[0] ? box : null;
}
