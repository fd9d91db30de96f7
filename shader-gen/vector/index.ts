/**
 * Vector export in one call: the scene's circles and lines down to `minRadius` output pixels, as
 * SVG text, or why the scene has none (a node whose step is not made of mirrors, or too many).
 */
import type { Scene } from '../../nodes/core/scene.ts';
import { type FigureLayer, figureLayer } from '../figures/layer.ts';
import { type VectorOptions, vectorPicture } from './enumerate.ts';
import { type SvgResult, writeSvg } from './svg.ts';

export type SvgExport =
  | ({ readonly ok: true; readonly notes: readonly string[] } & SvgResult)
  | { readonly ok: false; readonly message: string; readonly nodeId?: string };

/**
 * With the render node's figures (Cayley graph, depth-first limit set) drawn over the tiling. A scene
 * whose tiling has no vector form but whose figures do (a group of matrix generators) is written as
 * its figures over the background, and a note says the tiling was left out.
 */
export function exportSvg(scene: Scene, options: VectorOptions): SvgExport {
  const figures: FigureLayer = figureLayer(scene, options.width, options.height);
  const picture = vectorPicture(scene, options);
  const hasFigures = figures.strokes.length + figures.dots.length > 0;
  if (!picture.ok && !hasFigures) return picture;
  const notes = [...figures.notes];
  if (!picture.ok) notes.push(`the tiling is left out: ${picture.message}`);
  const drawn = picture.ok ? picture : { edges: [], seeds: [] };
  return { ok: true, notes, ...writeSvg(scene, drawn, options.width, options.height, figures) };
}

export { MAX_VECTOR_ELEMENTS } from './enumerate.ts';
