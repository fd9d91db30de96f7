/**
 * Export: a PNG of the render at a chosen size (GPU, full quality) with the graph JSON embedded
 * under the "kleinflow" key (so the picture reopens its graph), and the GLSL shader as text.
 */
import type { Scene } from '../../nodes/core/scene.ts';
import type { GraphDoc } from '../../nodes/graph/document.ts';
import { compile, shadertoySource } from '../../shader-gen/compile.ts';
import { encodePng } from '../io/png.ts';
import type { Viewport } from '../viewport/viewport.ts';
import { documentJson, download, fileStem } from './files.ts';

export interface PngSize {
  readonly width: number;
  readonly height: number;
}

/** Renders and downloads the PNG; false when cancelled. */
export async function exportPng(
  viewport: Viewport,
  doc: GraphDoc,
  scene: Scene,
  size: PngSize,
  onProgress?: (fraction: number) => void,
): Promise<boolean> {
  const pixels = await viewport.renderToPixels({
    width: size.width,
    height: size.height,
    samples: Math.max(scene.samples, 16),
    view: doc.view,
    onProgress: (f) => {
      onProgress?.(f);
    },
  });
  if (!pixels) return false;
  const png = encodePng(
    { width: size.width, height: size.height, data: pixels },
    { kleinflow: documentJson(doc) },
  );
  download(`${fileStem(doc)}.png`, png as Uint8Array<ArrayBuffer>, 'image/png');
  return true;
}

/** The standalone fragment shader with every value baked in. */
export function exportGlsl(doc: GraphDoc, scene: Scene, flavour: 'webgl2' | 'shadertoy'): void {
  const source = flavour === 'shadertoy' ? shadertoySource(scene) : compile(scene, { baked: true }).source;
  download(`${fileStem(doc)}${flavour === 'shadertoy' ? '.shadertoy' : ''}.frag`, source, 'text/plain');
}
