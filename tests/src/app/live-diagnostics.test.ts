import { describe, expect, it } from 'vitest';
import type { LiveRef } from '../../../nodes/core/values.ts';
import { liveDiagnostics } from '../../../src/app/live-diagnostics.ts';
import type { LiveStatus } from '../../../src/viewport/live-media.ts';

const camera: LiveRef = { kind: 'webcam', nodeId: 'cam', label: '', src: '' };
const video: LiveRef = { kind: 'video', nodeId: 'vid', label: 'loop.webm', src: '' };
const codes = (ref: LiveRef, state: LiveStatus) => liveDiagnostics([ref], () => state).map((d) => d.code);

describe('live source messages on the image node', () => {
  it('the camera: off → KF321 (press Start camera), failed → KF320 with the reason, live → none', () => {
    expect(codes(camera, { status: 'off' })).toEqual(['KF321']);
    const failed = liveDiagnostics([camera], () => ({ status: 'failed', reason: 'no camera was found' }));
    expect(failed).toMatchObject([{ code: 'KF320', nodeId: 'cam', severity: 'warning' }]);
    expect(failed[0].message).toContain('no camera was found');
    expect(failed[0].message).toContain('fallback picture');
    expect(codes(camera, { status: 'starting' })).toEqual([]);
    expect(codes(camera, { status: 'live' })).toEqual([]);
  });

  it('a video: not chosen → KF322 naming the file, unplayable → KF323, playing → none', () => {
    const missing = liveDiagnostics([video], () => ({ status: 'off' }));
    expect(missing).toMatchObject([{ code: 'KF322', nodeId: 'vid' }]);
    expect(missing[0].message).toContain('loop.webm');
    expect(codes(video, { status: 'failed', reason: 'bad file' })).toEqual(['KF323']);
    expect(codes(video, { status: 'live' })).toEqual([]);
  });

  it('asks the state of each node’s own source', () => {
    const asked: string[] = [];
    liveDiagnostics([camera, video], (id) => {
      asked.push(id);
      return { status: 'live' };
    });
    expect(asked).toEqual(['webcam', 'video:vid']);
  });
});
