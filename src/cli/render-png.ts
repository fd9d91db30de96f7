/**
 * Scene → PNG bytes on the CPU, with the graph's JSON embedded (iTXt "kleinflow") so the picture
 * reopens as its graph. Shared by `kleinflow render` and `npm run render-examples`; a 3D graph is
 * drawn by the CPU sphere tracer (shader-gen/space/render-3d.ts) on worker threads.
 */
import type { Scene } from '../../nodes/core/scene.ts';
import type { Scene3d } from '../../nodes/core/scene-3d.ts';
import { insetSpaceView } from '../../nodes/geometry/space/sphairahedron-space-picture.ts';
import type { SpaceViewTarget } from '../../nodes/graph/space-view.ts';
import { figureLayer } from '../../shader-gen/figures/layer.ts';
import { paintFigures } from '../../shader-gen/figures/paint.ts';
import { rasterize } from '../../shader-gen/raster.ts';
import { paintSceneLimitSets3d } from '../../shader-gen/space/limit-dots-3d.ts';
import { encodePng } from '../io/png.ts';
import { PNG_GRAPH_KEY } from './load-graph.ts';
import { type Pool3dRequest, renderScene3dOnPool } from './render-3d-pool.ts';
import { scenePictures } from './scene-pictures.ts';

export interface PngRequest {
  readonly width: number;
  readonly height: number;
  /** Samples per pixel; the render node's setting when absent. */
  readonly samples?: number;
  /** Called after each row with the fraction done (0..1]. */
  readonly onProgress?: (done: number) => void;
}

/** `graphText` null: no graph inside (gallery thumbnails, which only ever show). */
export function renderScenePng(scene: Scene, graphText: string | null, request: PngRequest): Uint8Array {
  const image = rasterize(scene, {
    pictures: scenePictures(scene),
    width: request.width,
    height: request.height,
    samples: request.samples,
    onProgress: keepGoing(request.onProgress),
  });
  // The render node's figures (Cayley graph, depth-first limit set) over the picture.
  paintFigures(image, scene.view, figureLayer(scene, request.width, request.height));
  return encodeWithGraph(image, graphText);
}

const encodeWithGraph = (image: Parameters<typeof encodePng>[0], graphText: string | null) =>
  encodePng(image, graphText === null ? {} : { [PNG_GRAPH_KEY]: graphText });

/** A progress callback that never cancels (the renderers stop when their callback says false). */
const keepGoing = (onProgress?: (done: number) => void) =>
  onProgress
    ? (done: number) => {
        onProgress(done);
        return true;
      }
    : undefined;

/**
 * A 3D graph's picture: the CPU sphere tracer at the graph's camera, in bands over `threads`
 * worker threads (render-3d-pool.ts), limit-set dots painted over it, graph embedded like 2D; with
 * `space`, the graph's parameter-space view as a panel in the lower right corner.
 */
export async function renderScene3dPngOnPool(
  scene: Scene3d,
  graphText: string | null,
  request: Pool3dRequest,
  space: SpaceViewTarget | null = null,
): Promise<Uint8Array> {
  const image = await renderScene3dOnPool(scene, request);
  // The quaternion groups' limit sets (Fig. 6) are dots over the traced picture, as in the app.
  paintSceneLimitSets3d(scene, image);
  // A parameter-space view in the graph: its panel in the corner (docs/math-3d.md "The parameter-space view").
  if (space) insetSpaceView(image, space);
  return encodeWithGraph(image, graphText);
}
