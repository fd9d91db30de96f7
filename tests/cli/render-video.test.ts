/**
 * `kleinflow render --frames … --out x.mp4 | x.webm`: the real executable writes a video that
 * mediabunny reads back with the codec, size, frame count and duration asked for, and whose
 * decoded frame shows the CPU's picture of that time (loosely: the codecs are lossy).
 */
import { readFileSync } from 'node:fs';
import { join } from 'node:path';
import { registerMediabunnyServer } from '@mediabunny/server';
import { ALL_FORMATS, BufferSource, Input, VideoSampleSink } from 'mediabunny';
import { beforeAll, describe, expect, it } from 'vitest';
import { registry } from '../../nodes/types/index.ts';
import { renderFrameAt } from '../../src/cli/frame-render.ts';
import { openDocumentText } from '../../src/io/document-io.ts';
import { cliTempDir, ROOT, runCli } from './run-cli.ts';

const ART = join(ROOT, 'examples/fig43-tessellation-artwork.kleinflow.json');
/** One frame a second of the 12 s loop, one sample, one worker thread: seconds, not minutes. */
const QUICK = ['--fps', '1', '--samples', '1', '--threads', '1'];
const dir = cliTempDir('kleinflow-video-');

beforeAll(() => {
  registerMediabunnyServer({ hardwareContext: null }); // decoders for reading the files back
});

/** The file's video track: codec, size, packet count, duration and the RGBA frame shown at `time`. */
async function readVideo(path: string, time: number) {
  const input = new Input({ source: new BufferSource(readFileSync(path)), formats: ALL_FORMATS });
  const track = (await input.getPrimaryVideoTrack())!;
  const sample = (await new VideoSampleSink(track).getSample(time))!;
  const rgba = new Uint8Array(sample.allocationSize({ format: 'RGBA' }));
  await sample.copyTo(rgba, { format: 'RGBA' });
  const shown = { timestamp: sample.timestamp, duration: sample.duration };
  sample.close();
  return {
    codec: await track.getCodec(),
    width: track.displayWidth,
    height: track.displayHeight,
    frames: (await track.computePacketStats()).packetCount,
    duration: await input.computeDuration(),
    shown,
    rgba,
  };
}

const BLOCK = 4;

/**
 * Mean absolute difference (0–255) of the colours of two square RGBA pictures averaged over 4×4
 * blocks: a lossy codec at 64² smears the one-pixel tile edges (pixel by pixel the right frame is
 * ~11 levels off, as far as 25 from its neighbours), but the blocks' colours stay within ~2 levels,
 * while a frame one second off is ~10 away.
 */
function blockDifference(a: ArrayLike<number>, b: ArrayLike<number>, side: number): number {
  const n = side / BLOCK;
  const sums = new Float64Array(n * n * 3);
  for (let y = 0; y < side; y++)
    for (let x = 0; x < side; x++)
      for (let k = 0; k < 3; k++) {
        const at = (y * side + x) * 4 + k;
        sums[(Math.floor(y / BLOCK) * n + Math.floor(x / BLOCK)) * 3 + k] += a[at] - b[at];
      }
  let total = 0;
  for (const sum of sums) total += Math.abs(sum) / (BLOCK * BLOCK);
  return total / sums.length;
}

function cpuFrame(time: number, width: number, height: number) {
  const opened = openDocumentText(readFileSync(ART, 'utf8'), registry);
  if (!opened.ok) throw new Error('the example does not load');
  return renderFrameAt(opened.doc, time, { width, height, samples: 1 }).data;
}

describe('kleinflow render --frames … --out video', () => {
  it('writes one exact loop as H.264 MP4: 12 frames at 1 fps, 12 s, the CPU picture in each', async () => {
    const mp4 = join(dir, 'loop.mp4');
    const r = runCli(['render', ART, '--frames', 'loop', '--size', '64x64', '--out', mp4, ...QUICK]);
    expect(r.stderr).toBe(''); // no FFmpeg hardware-probing noise
    expect(r.status).toBe(0);
    expect(r.stdout).toContain('wrote 12 frames of 12 at 1 fps');
    const video = await readVideo(mp4, 5);
    expect(video.codec).toBe('avc');
    expect([video.width, video.height]).toEqual([64, 64]);
    // One loop (12 s) at 1 fps: frames at 0 … 11 s, the last shown until 12 s, where frame 0 follows.
    expect(video.frames).toBe(12);
    expect(video.duration).toBeCloseTo(12, 3);
    expect(video.shown.timestamp).toBeCloseTo(5, 3);
    expect(video.shown.duration).toBeCloseTo(1, 3);
    expect(blockDifference(video.rgba, cpuFrame(5, 64, 64), 64)).toBeLessThan(4);
    // The comparison tells frames apart: the pictures of the seconds before and after are far off.
    expect(blockDifference(video.rgba, cpuFrame(4, 64, 64), 64)).toBeGreaterThan(6);
    expect(blockDifference(video.rgba, cpuFrame(6, 64, 64), 64)).toBeGreaterThan(6);
  }, 60_000);

  it('writes VP9 WebM of a --frame-range from 0 s, rendering an odd size one pixel smaller', async () => {
    const webm = join(dir, 'part.webm');
    const range = ['--frame-range', '7:10'];
    const r = runCli([
      'render',
      ART,
      '--frames',
      'loop',
      ...range,
      '--size',
      '33x32',
      '--out',
      webm,
      ...QUICK,
    ]);
    expect(r.status).toBe(0);
    expect(r.stderr).toBe('note: a video needs even sides: 33×32 is rendered at 32×32\n');
    const video = await readVideo(webm, 0);
    expect(video.codec).toBe('vp9');
    expect([video.width, video.height, video.frames]).toEqual([32, 32, 3]);
    expect(video.duration).toBeCloseTo(3, 3);
    // The file's first frame is frame 7 of the loop (t = 7 s).
    expect(blockDifference(video.rgba, cpuFrame(7, 32, 32), 32)).toBeLessThan(4);
    expect(blockDifference(video.rgba, cpuFrame(0, 32, 32), 32)).toBeGreaterThan(6);
  }, 60_000);
});
