/**
 * The "Export animation…" dialog: format (the video formats this browser can encode, and GIF),
 * size, frames per second, duration — "one loop" when the graph's cycles have a common period
 * (nodes/graph/loop-period.ts), or seconds — and samples per pixel; a progress bar with Cancel
 * while the frames are rendered at t = i/fps (src/app/animation-export.ts).
 */

import { useEffect, useRef, useState } from 'react';
import { LIMITS, type View } from '../../../nodes/core/scene.ts';
import { loopFrameCount, loopIsFrameExact } from '../../../nodes/graph/frame-times.ts';
import type { LoopPeriod } from '../../../nodes/graph/loop-period.ts';
import { ANIMATION_FORMATS, type AnimationFormat, evenSize } from '../../io/animation-formats.ts';
import type { AnimationExportOptions } from '../animation-export.ts';
import { useModalDialog } from '../use-modal-dialog.ts';
import type { Size } from './ExportDialog.tsx';
import { ExportDialogShell, ExportRunFooter } from './ExportDialogShell.tsx';
import { useExportRun } from './use-export-run.ts';

interface Props {
  readonly viewSize: Size;
  readonly view: View;
  readonly defaultSamples: number;
  readonly loop: LoopPeriod;
  /** Records and downloads; resolves false when cancelled. `onProgress` returning false cancels. */
  run(o: AnimationExportOptions, onProgress: (f: number) => boolean): Promise<boolean>;
  onClose(): void;
}

const FORMAT_ORDER: readonly AnimationFormat[] = ['webm-vp9', 'webm-vp8', 'mp4-avc', 'gif'];
const MAX_SIDE = 4096;
const MAX_FPS = 120;
const MAX_SECONDS = 600;
/** Default frame height: small enough to record quickly, big enough to look at. */
const DEFAULT_HEIGHT = 480;

const clampInt = (v: number, lo: number, hi: number) => Math.min(hi, Math.max(lo, Math.round(v) || lo));

/** What the loop period means for the user, in one sentence. */
function loopNote(loop: LoopPeriod, fps: number): string {
  if (loop.kind === 'static')
    return 'Nothing in this graph changes with time: every frame is the same picture.';
  if (loop.kind === 'none') return `No loop: ${loop.reason}.`;
  const frames = loopFrameCount(loop.seconds, fps);
  return loopIsFrameExact(loop.seconds, fps)
    ? `One loop is ${+loop.seconds.toFixed(6)} s = ${frames} frames; played in a loop, the last frame meets the first.`
    : `One loop is ${+loop.seconds.toFixed(6)} s, not a whole number of frames at ${fps} fps: pick an fps that divides it for a seamless loop.`;
}

export function AnimationExportDialog({ viewSize, view, defaultSamples, loop, run, onClose }: Props) {
  const dialog = useModalDialog(onClose);
  const aspect = viewSize.width / Math.max(1, viewSize.height);
  const [width, setWidth] = useState(evenSize(Math.round(DEFAULT_HEIGHT * aspect)));
  const [height, setHeight] = useState(DEFAULT_HEIGHT);
  const [fps, setFps] = useState(24);
  const [oneLoop, setOneLoop] = useState(loop.kind === 'loop');
  const [seconds, setSeconds] = useState(loop.kind === 'loop' ? Math.min(loop.seconds, MAX_SECONDS) : 4);
  const [samples, setSamples] = useState(clampInt(defaultSamples, 1, LIMITS.maxSamples));
  const [format, setFormat] = useState<AnimationFormat>('gif');
  const [supported, setSupported] = useState<Record<AnimationFormat, boolean> | null>(null);
  const { progress, error, ...exportRun } = useExportRun(onClose);
  const chosen = useRef(false);

  // Ask the browser's encoders what they can do at this size; pick the first that works.
  useEffect(() => {
    let live = true;
    void import('../animation-encoders.ts')
      .then((m) => m.supportedFormats({ width, height, fps }))
      .then((s) => {
        if (!live) return;
        setSupported(s);
        if (!chosen.current) setFormat(FORMAT_ORDER.find((f) => s[f]) ?? 'gif');
        else setFormat((f) => (s[f] ? f : 'gif'));
      });
    return () => {
      live = false;
    };
  }, [width, height, fps]);

  const frames =
    oneLoop && loop.kind === 'loop'
      ? loopFrameCount(loop.seconds, fps)
      : Math.max(1, Math.round(seconds * fps));
  const video = format !== 'gif';
  const size = { width: video ? evenSize(width) : width, height: video ? evenSize(height) : height };
  const busy = progress !== null;
  const noVideo = supported !== null && !FORMAT_ORDER.some((f) => f !== 'gif' && supported[f]);

  const start = async () => {
    const referenceHeight = viewSize.height * (window.devicePixelRatio || 1);
    await exportRun.start((onProgress) =>
      run({ format, ...size, fps, frames, samples, view, referenceHeight }, onProgress),
    );
  };
  const close = exportRun.close;

  return (
    <ExportDialogShell
      dialogRef={dialog.ref}
      title="Export animation"
      lead={
        <>
          Every frame is rendered on the GPU at t = frame ÷ fps with the full sample count, like the PNG
          export.
        </>
      }
      onClose={close}
    >
      <div className="kf-export__grid">
        <label htmlFor="kf-anim-format">Format</label>
        <select
          id="kf-anim-format"
          data-checked={supported !== null}
          value={format}
          disabled={busy}
          onChange={(e) => {
            chosen.current = true;
            setFormat(e.target.value as AnimationFormat);
          }}
        >
          {FORMAT_ORDER.map((f) => (
            <option key={f} value={f} disabled={supported !== null && !supported[f]}>
              {ANIMATION_FORMATS[f].label}
              {supported === null || supported[f] ? '' : ' (no encoder in this browser)'}
            </option>
          ))}
        </select>
        <span>Size</span>
        <span className="kf-export__dims">
          <input
            type="number"
            aria-label="Width in pixels"
            min={2}
            max={MAX_SIDE}
            value={width}
            disabled={busy}
            onChange={(e) => setWidth(clampInt(Number(e.target.value), 2, MAX_SIDE))}
          />
          ×
          <input
            type="number"
            aria-label="Height in pixels"
            min={2}
            max={MAX_SIDE}
            value={height}
            disabled={busy}
            onChange={(e) => setHeight(clampInt(Number(e.target.value), 2, MAX_SIDE))}
          />
          {video && (size.width !== width || size.height !== height) && (
            <span className="kf-export__note">
              {' '}
              video sides are even: {size.width} × {size.height}
            </span>
          )}
        </span>
        <label htmlFor="kf-anim-fps">Frames/s</label>
        <input
          id="kf-anim-fps"
          type="number"
          min={1}
          max={MAX_FPS}
          value={fps}
          disabled={busy}
          onChange={(e) => setFps(clampInt(Number(e.target.value), 1, MAX_FPS))}
        />
        <span>Duration</span>
        <span className="kf-export__radios" role="radiogroup" aria-label="Duration">
          <label>
            <input
              type="radio"
              name="kf-anim-duration"
              checked={oneLoop && loop.kind === 'loop'}
              disabled={busy || loop.kind !== 'loop'}
              onChange={() => setOneLoop(true)}
            />
            One loop
          </label>
          <label>
            <input
              type="radio"
              name="kf-anim-duration"
              checked={!oneLoop || loop.kind !== 'loop'}
              disabled={busy}
              onChange={() => setOneLoop(false)}
            />
            <input
              type="number"
              aria-label="Duration in seconds"
              min={0.05}
              max={MAX_SECONDS}
              step={0.5}
              value={seconds}
              disabled={busy}
              onChange={(e) => {
                setOneLoop(false);
                setSeconds(Math.min(MAX_SECONDS, Math.max(0.05, Number(e.target.value) || 0.05)));
              }}
            />{' '}
            s
          </label>
        </span>
        <label htmlFor="kf-anim-samples">Samples</label>
        <span>
          <input
            id="kf-anim-samples"
            type="number"
            min={1}
            max={LIMITS.maxSamples}
            value={samples}
            disabled={busy}
            onChange={(e) => setSamples(clampInt(Number(e.target.value), 1, LIMITS.maxSamples))}
          />
          <span className="kf-export__note"> per pixel, every frame</span>
        </span>
      </div>
      <p className="kf-export__note" data-testid="anim-loop-note">
        {loopNote(loop, fps)} {frames} frames will be rendered.
      </p>
      {noVideo && (
        <p className="kf-export__note" role="status">
          This browser has no WebCodecs video encoder for VP9, VP8 or H.264, so only GIF can be written here
          (Chrome, Edge and Firefox desktop can write video).
        </p>
      )}
      <ExportRunFooter
        progress={progress}
        progressText={(progress) =>
          `Rendering frame ${Math.min(frames, Math.floor(progress * frames) + 1)} of ${frames}…`
        }
        error={error}
        startLabel={`Export ${frames} frames`}
        onStart={() => void start()}
        onCancel={exportRun.cancel}
        onClose={close}
      />
    </ExportDialogShell>
  );
}
