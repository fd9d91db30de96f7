/**
 * "Export SVG…": the scene's circles and lines (shader-gen/vector) at the live view and size,
 * downloaded as `<title>.svg`. Returns the sentence the toast shows, success or why not.
 */
import type { Scene, View } from '../../nodes/core/scene.ts';
import type { GraphDoc } from '../../nodes/graph/document.ts';
import { exportSvg } from '../../shader-gen/vector/index.ts';
import { download, fileStem } from './files.ts';

/** Circles under this radius in output pixels are left out (the CLI's default too). */
const MIN_RADIUS_PX = 1;

export function exportSvgFile(
  doc: GraphDoc,
  scene: Scene,
  view: View,
  size: { readonly width: number; readonly height: number },
): { readonly ok: boolean; readonly message: string } {
  const width = Math.max(1, Math.round(size.width));
  const height = Math.max(1, Math.round(size.height));
  const result = exportSvg({ ...scene, view }, { width, height, minRadius: MIN_RADIUS_PX });
  if (!result.ok) return { ok: false, message: `No SVG: ${result.message}.` };
  download(`${fileStem(doc)}.svg`, result.svg, 'image/svg+xml');
  const seeds = result.seedCount > 0 ? ` and ${result.seedCount} seed disks` : '';
  const figures = result.figureCount > 0 ? `, ${result.figureCount} figure strokes and points` : '';
  const notes = result.notes.map((n) => ` ${n}.`).join('');
  return {
    ok: true,
    message: `Exported ${width} × ${height} SVG: ${result.edgeCount} circles and lines${seeds}${figures} (radius ≥ ${MIN_RADIUS_PX} px).${notes}`,
  };
}
