/**
 * The image node's live-source controls in the inspector: "Start camera" / "Stop camera" for
 * source webcam, "Choose video…" for source video. A chosen video plays at once from the file;
 * the document keeps its name and, when it is small (LIMITS.maxVideoDataUrlChars), the video
 * itself, so a short loop travels with the document. The camera stream is never kept.
 */

import { LIMITS } from '../../nodes/core/limits.ts';
import { liveSourceId } from '../../nodes/core/live-source.ts';
import type { GraphNode } from '../../nodes/graph/document.ts';
import { useStore } from '../state/use-store.ts';
import { liveMedia } from '../viewport/live-media.ts';
import { FileChoice } from './FileChoice.tsx';
import { readDataUrl } from './picture-file.ts';
import { useLiveMediaVersion } from './use-live-sources.ts';

/** A file small enough to keep: its base64 data: URL (≈ 4/3 of its bytes) fits the limit. */
const keepable = (file: File) => (file.size * 4) / 3 + 200 <= LIMITS.maxVideoDataUrlChars;

export function LiveSourceSection({ node }: { node: GraphNode }) {
  const store = useStore();
  useLiveMediaVersion();
  const source = node.params.source;
  if (node.type !== 'image' || (source !== 'webcam' && source !== 'video')) return null;
  const id = liveSourceId({ kind: source, nodeId: node.id, label: '', src: '' });
  const state = liveMedia.state(id);
  const status =
    state.status === 'failed'
      ? `not running: ${state.reason}`
      : state.status === 'live'
        ? 'live'
        : state.status;

  const choose = async (file: File | undefined) => {
    if (!file) return;
    void liveMedia.startVideo(id, URL.createObjectURL(file), file.name, true);
    const videoSrc = keepable(file) ? await readDataUrl(file) : '';
    store.dispatch(
      { type: 'set-params', patches: [{ nodeId: node.id, params: { video: file.name, videoSrc } }] },
      'choose video',
    );
  };

  return (
    <>
      <h3>Live source</h3>
      <p className="kf-inspector__hint" data-testid="live-status">
        {source === 'webcam' ? 'Camera' : 'Video'}: {status}
      </p>
      {source === 'webcam' ? (
        state.status === 'live' || state.status === 'starting' ? (
          <button type="button" className="kf-button" onClick={() => liveMedia.stop(id)}>
            Stop camera
          </button>
        ) : (
          <button type="button" className="kf-button" onClick={() => void liveMedia.startCamera()}>
            Start camera
          </button>
        )
      ) : (
        <FileChoice label="Choose video" accept="video/*" onFile={(f) => void choose(f)} />
      )}
      <p className="kf-inspector__hint">
        Drawn live in the browser only; the picture below is the fallback. The camera is never recorded or
        saved.
      </p>
    </>
  );
}
