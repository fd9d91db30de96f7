/**
 * A worker thread of `kleinflow render --frames`: renders frame i of a graph at t = i/fps and
 * answers with its PNG (graph embedded) or raw RGBA (for a GIF or a video, which take the frames in order
 * on the main thread). The document is parsed once per worker, not once per frame.
 */
import { parentPort } from 'node:worker_threads';
import type { GraphDoc } from '../../nodes/graph/document.ts';
import { frameTime } from '../../nodes/graph/frame-times.ts';
import { registry } from '../../nodes/types/index.ts';
import { openDocumentText } from '../io/document-io.ts';
import { encodePng } from '../io/png.ts';
import { type FrameRequest, renderFrameAt } from './frame-render.ts';
import { PNG_GRAPH_KEY } from './load-graph.ts';

export interface FrameJob extends FrameRequest {
  /** The Kleinflow document text (also embedded in each PNG). */
  readonly text: string;
  readonly index: number;
  readonly fps: number;
  readonly encode: 'png' | 'rgba';
}

export type FrameResult =
  | { readonly index: number; readonly bytes: Uint8Array; readonly ms: number }
  | { readonly index: number; readonly error: string };

let parsed: { text: string; doc: GraphDoc } | undefined;

function docOf(text: string): GraphDoc {
  if (parsed?.text !== text) {
    const opened = openDocumentText(text, registry);
    if (!opened.ok) throw new Error('the document does not load');
    parsed = { text, doc: opened.doc };
  }
  return parsed.doc;
}

export function runFrameJob(job: FrameJob): FrameResult {
  const started = performance.now();
  try {
    const image = renderFrameAt(docOf(job.text), frameTime(job.index, job.fps), job);
    const bytes =
      job.encode === 'png'
        ? encodePng(image, { [PNG_GRAPH_KEY]: job.text })
        : new Uint8Array(image.data.buffer, image.data.byteOffset, image.data.byteLength);
    return { index: job.index, bytes, ms: performance.now() - started };
  } catch (e) {
    return { index: job.index, error: e instanceof Error ? e.message : String(e) };
  }
}

parentPort?.on('message', (job: FrameJob) => {
  const result = runFrameJob(job);
  parentPort?.postMessage(result, 'bytes' in result ? [result.bytes.buffer as ArrayBuffer] : []);
});
