/**
 * The first view of an imported Flower graph: the region Flower itself showed. Flower's render
 * canvas opens with the origin at its centre and 100 world units across its height (its
 * constructionCanvas2d: translate (0, 0), scale 100 — the same meaning as Kleinflow's view
 * scale), and Flower graphs are drawn around the origin. When the construction (every point,
 * line end and circle, as evaluated) reaches further out, the view grows to hold it all.
 */
import type { OverlayItem, View } from '../../../nodes/core/scene.ts';
import type { Vec2 } from '../../../nodes/core/values.ts';

/** Flower's initial camera. */
export const FLOWER_VIEW: View = { center: [0, 0], scale: 100 };
/** Room around the farthest construction point when the view must grow (a fraction of its size). */
const MARGIN = 1.1;

export function flowerView(overlays: readonly OverlayItem[]): View {
  const pts: Vec2[] = [];
  for (const { shape } of overlays) {
    if (shape.shape === 'point') pts.push(shape.at);
    else if (shape.shape === 'line') pts.push(shape.line.a, shape.line.b);
    else {
      const { c, r } = shape.circle;
      pts.push([c[0] - r, c[1] - r], [c[0] + r, c[1] + r]);
    }
  }
  let reach = 0;
  for (const [x, y] of pts) {
    if (Number.isFinite(x) && Number.isFinite(y)) reach = Math.max(reach, Math.abs(x), Math.abs(y));
  }
  const needed = Math.ceil(2 * reach * MARGIN);
  return { center: FLOWER_VIEW.center, scale: Math.max(FLOWER_VIEW.scale, needed) };
}
