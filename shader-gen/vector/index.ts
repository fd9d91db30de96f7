/**
 * Vector export in one call: the scene's circles and lines down to `minRadius` output pixels, as
 * SVG text, or why the scene has none (a node whose step is not made of mirrors, or too many).
 */
import type { Scene } from '../../nodes/core/scene.ts';
import { type VectorOptions, vectorPicture } from './enumerate.ts';
import { type SvgResult, writeSvg } from './svg.ts';

export type SvgExport =
  | ({ readonly ok: true } & SvgResult)
  | { readonly ok: false; readonly message: string; readonly nodeId?: string };

export function exportSvg(scene: Scene, options: VectorOptions): SvgExport {
  const picture = vectorPicture(scene, options);
  if (!picture.ok) return picture;
  return { ok: true, ...writeSvg(scene, picture, options.width, options.height) };
}

export { MAX_VECTOR_ELEMENTS } from './enumerate.ts';
