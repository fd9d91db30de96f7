/**
 * The live sources the drawn scene asks for, kept in step with the page's media (live-media.ts):
 * a video kept in the document starts playing (muted, so no gesture is needed), a source no node
 * asks for any more is stopped (the camera light goes off), videos follow the animation time when
 * the document has a Time node, and the node messages say why a fallback picture is drawn. The
 * camera itself is never started here: only `startCamera`, from a click, asks for it.
 */
import { useEffect, useMemo, useState } from 'react';
import type { Diagnostic } from '../../nodes/core/diagnostics.ts';
import { liveSourceId, tileLiveSources } from '../../nodes/core/live-source.ts';
import type { GraphDoc } from '../../nodes/graph/document.ts';
import type { Evaluation } from '../../nodes/graph/evaluate.ts';
import { liveMedia } from '../viewport/live-media.ts';
import { liveDiagnostics } from './live-diagnostics.ts';

export interface LiveSources {
  readonly diagnostics: Diagnostic[];
  /** A node wants the camera and it is not running (show "Start camera"). */
  readonly cameraWanted: boolean;
}

/** Re-renders whenever a live source starts, stops or fails. */
export function useLiveMediaVersion(): number {
  const [version, setVersion] = useState(0);
  useEffect(() => liveMedia.subscribe(() => setVersion((v) => v + 1)), []);
  return version;
}

export function useLiveSources(evaluation: Evaluation, doc: GraphDoc, time: number): LiveSources {
  const version = useLiveMediaVersion();
  const refs = useMemo(
    () => (evaluation.scene3d ? [] : tileLiveSources(evaluation.scene.tile)),
    [evaluation],
  );

  useEffect(() => {
    const wanted = new Set(refs.map(liveSourceId));
    for (const ref of refs) {
      const id = liveSourceId(ref);
      if (ref.kind !== 'video' || ref.src === '') continue;
      // A kept video plays unless this node already plays the file of that name.
      const running = liveMedia.state(id).status !== 'off' && liveMedia.videoName(id) === ref.label;
      if (!running) void liveMedia.startVideo(id, ref.src, ref.label);
    }
    for (const id of liveMedia.ids()) if (!wanted.has(id)) liveMedia.stop(id);
  }, [refs]);

  const timeline = doc.nodes.some((n) => n.type === 'time');
  useEffect(() => liveMedia.setClock(timeline ? time : null), [timeline, time]);

  return useMemo(() => {
    void version; // the media's state is read below
    const camera = refs.some((r) => r.kind === 'webcam');
    const status = liveMedia.state('webcam').status;
    return {
      diagnostics: liveDiagnostics(refs, (id) => liveMedia.state(id)),
      cameraWanted: camera && (status === 'off' || status === 'failed'),
    };
  }, [refs, version]);
}
