/**
 * The node messages of live sources (camera, video), from what the page's media can do now: the
 * node says why its fallback picture is drawn (camera off, denied or absent; video not chosen or
 * unplayable), so a missing camera is a clear message and never a broken picture.
 */
import { type Diagnostic, diag } from '../../nodes/core/diagnostics.ts';
import { liveSourceId } from '../../nodes/core/live-source.ts';
import type { LiveRef } from '../../nodes/core/values.ts';
import type { LiveStatus } from '../viewport/live-media.ts';

export function liveDiagnostics(refs: readonly LiveRef[], stateOf: (id: string) => LiveStatus): Diagnostic[] {
  return refs.flatMap((ref) => {
    const state = stateOf(liveSourceId(ref));
    const at = { nodeId: ref.nodeId, port: 'source' };
    if (ref.kind === 'webcam') {
      if (state.status === 'failed') return [diag('cameraUnavailable', at, state.reason)];
      return state.status === 'off' ? [diag('cameraOff', at)] : [];
    }
    if (state.status === 'failed') return [diag('videoUnplayable', at, state.reason)];
    return state.status === 'off' ? [diag('videoMissing', at, ref.label)] : [];
  });
}
