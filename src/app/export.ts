/**
 * Export: a PNG of the render at a chosen size (GPU, tiled, full quality) with the graph embedded
 * (png-graph.ts, so the picture reopens its graph), and the GLSL shader as text.
 */
import type { Scene, View } from '../../nodes/core/scene.ts';
import type { GraphDoc } from '../../nodes/graph/document.ts';
import { figureLayer } from '../../shader-gen/figures/layer.ts';
import { paintFigures } from '../../shader-gen/figures/paint.ts';
import { paintSceneLimitSets3d } from '../../shader-gen/space/limit-dots-3d.ts';
import { standaloneShader } from '../../shader-gen/standalone.ts';
import { embedGraph } from '../io/png-graph.ts';
import { type Drawable, is3d } from '../viewport/drawable.ts';
import type { Viewport } from '../viewport/viewport.ts';
import { download, fileStem } from './files.ts';

export interface PngExportOptions {
  readonly width: number;
  readonly height: number;
  readonly samples: number;
  /** Pixels outside the tiling keep alpha 0 instead of the background colour. */
  readonly transparent: boolean;
  readonly view: View;
  /**
   * Height in device pixels of the picture the export should look like (the live view): tile
   * edges are drawn in pixels, so they are widened by height / referenceHeight to keep their look.
   */
  readonly referenceHeight: number;
}

/** The scene with its pixel-sized tile edges widened by `factor` (edge px × factor). */
export function scaleEdges(scene: Scene, factor: number): Scene {
  if (scene.tile.edgeWidth <= 0 || factor === 1) return scene;
  return { ...scene, tile: { ...scene.tile, edgeWidth: scene.tile.edgeWidth * factor } };
}

/**
 * The PNG bytes (graph embedded), or null when `onProgress` returned false (cancelled). A 3D view
 * exports what it shows: its scene through the view's camera, by the same generator at the new size.
 */
export async function renderPng(
  viewport: Viewport,
  doc: GraphDoc,
  scene: Scene,
  o: PngExportOptions,
  onProgress?: (fraction: number) => boolean,
): Promise<Uint8Array | null> {
  const live = viewport.drawing();
  const pixels = await viewport.renderToPixels({
    width: o.width,
    height: o.height,
    samples: o.samples,
    view: o.view,
    transparent: o.transparent,
    scene: live && is3d(live) ? live : scaleEdges(scene, o.height / o.referenceHeight),
    onProgress,
  });
  if (!pixels) return null;
  if (live && is3d(live) && live.limitSets?.length) {
    // Fig. 6: the quaternion groups' limit-set dots, as the view's overlay paints them.
    const seen = doc.camera3d ? { ...live, camera: doc.camera3d } : live;
    paintSceneLimitSets3d(seen, { width: o.width, height: o.height, data: pixels });
  }
  if (!(live && is3d(live))) {
    // The render node's figures (Cayley graph, depth-first limit set), as the live overlay draws
    // them: enumerated for the live view's pixel size, widened like the tile edges.
    const k = o.height / o.referenceHeight;
    const layer = figureLayer({ ...scene, view: o.view }, o.width / k, o.referenceHeight);
    paintFigures({ width: o.width, height: o.height, data: pixels }, o.view, layer, k);
  }
  return embedGraph({ width: o.width, height: o.height, data: pixels }, doc);
}

/** Renders and downloads `<title>.png`; false when cancelled. */
export async function exportPng(
  viewport: Viewport,
  doc: GraphDoc,
  scene: Scene,
  o: PngExportOptions,
  onProgress?: (fraction: number) => boolean,
): Promise<boolean> {
  const png = await renderPng(viewport, doc, scene, o, onProgress);
  if (!png) return false;
  download(`${fileStem(doc)}.png`, png as Uint8Array<ArrayBuffer>, 'image/png');
  return true;
}

/**
 * `<title>.frag`: the standalone WebGL2 shader, values baked; `<title>.shadertoy.glsl` for Shadertoy
 * (shader-gen/standalone.ts, as `kleinflow glsl`). A 3D graph's Shadertoy version bakes the camera
 * the view shows (the document's view camera, else the render node's). Returns the toast's sentence.
 */
export function exportGlsl(doc: GraphDoc, picture: Drawable, flavour: 'webgl2' | 'shadertoy'): string {
  const shown = is3d(picture) && doc.camera3d ? { ...picture, camera: doc.camera3d } : picture;
  const { source } = standaloneShader(shown, flavour);
  const name = `${fileStem(doc)}${flavour === 'shadertoy' ? '.shadertoy.glsl' : '.frag'}`;
  download(name, source, 'text/plain');
  const what = is3d(picture) ? 'sphere-tracing shader' : 'shader';
  return flavour === 'shadertoy'
    ? `Exported the Shadertoy ${what} ${name}: paste it into a new shader on shadertoy.com.`
    : `Exported the GLSL ${what} ${name} (every value baked in; the frame uniforms are listed at its top).`;
}
