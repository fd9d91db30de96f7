/**
 * "Export animation…": frame i is the graph evaluated at t = i/fps (nodes/graph/frame-times.ts)
 * and rendered like the PNG export — tiled on the GPU at the full sample count, never a screen
 * capture — then handed in order to the file's encoder (src/io/animation-sink.ts). A video source is
 * sought to t (modulo its length) before each frame, so the video plays in the file.
 */
import { hasErrors } from '../../nodes/core/diagnostics.ts';
import type { View } from '../../nodes/core/scene.ts';
import type { GraphDoc } from '../../nodes/graph/document.ts';
import { evaluateGraph } from '../../nodes/graph/evaluate.ts';
import { frameTime } from '../../nodes/graph/frame-times.ts';
import { registry } from '../../nodes/types/index.ts';
import { ANIMATION_FORMATS, type AnimationFormat } from '../io/animation-formats.ts';
import { liveMedia } from '../viewport/live-media.ts';
import type { Viewport } from '../viewport/viewport.ts';
import { scaleEdges } from './export.ts';
import { download, fileStem } from './files.ts';

export interface AnimationExportOptions {
  readonly format: AnimationFormat;
  readonly width: number;
  readonly height: number;
  readonly fps: number;
  readonly frames: number;
  readonly samples: number;
  readonly view: View;
  /** Device-pixel height of the live view: tile edges are widened by height / referenceHeight (export.ts). */
  readonly referenceHeight: number;
}

/** The file's bytes, or null when `onProgress` returned false (cancelled). */
export async function recordAnimation(
  viewport: Viewport,
  doc: GraphDoc,
  o: AnimationExportOptions,
  onProgress: (fraction: number) => boolean,
): Promise<Uint8Array | null> {
  const { createSink } = await import('../io/animation-sink.ts');
  const sink = await createSink(o.format, o);
  let finished = false;
  try {
    for (let i = 0; i < o.frames; i++) {
      const time = frameTime(i, o.fps);
      const evaluation = evaluateGraph(doc, registry, { time });
      if (hasErrors(evaluation.diagnostics))
        throw new Error(`at t = ${time.toFixed(3)} s the graph has errors`);
      // A video shows its frame at this time (a camera shows what it sees now).
      await liveMedia.seekVideos(time);
      const pixels = await viewport.renderToPixels({
        width: o.width,
        height: o.height,
        samples: o.samples,
        view: o.view,
        transparent: false,
        scene: scaleEdges(evaluation.scene, o.height / o.referenceHeight),
        onProgress: (f) => onProgress((i + f) / o.frames),
      });
      if (!pixels) return null;
      await sink.add(pixels, i);
      if (!onProgress((i + 1) / o.frames)) return null;
    }
    const bytes = await sink.finish();
    finished = true;
    return bytes;
  } finally {
    liveMedia.followClock();
    if (!finished) await sink.cancel().catch(() => undefined);
  }
}

/** Records and downloads `<title>.webm|mp4|gif`; false when cancelled. */
export async function exportAnimation(
  viewport: Viewport,
  doc: GraphDoc,
  o: AnimationExportOptions,
  onProgress: (fraction: number) => boolean,
): Promise<boolean> {
  const bytes = await recordAnimation(viewport, doc, o, onProgress);
  if (!bytes) return false;
  const spec = ANIMATION_FORMATS[o.format];
  download(`${fileStem(doc)}.${spec.extension}`, bytes as Uint8Array<ArrayBuffer>, spec.mime);
  return true;
}
