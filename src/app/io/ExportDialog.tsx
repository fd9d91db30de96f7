/**
 * The PNG export dialog: size (presets from the live view's size up to LIMITS.maxImageSide),
 * samples per pixel, solid or transparent background; a progress bar with Cancel while the tiled
 * GPU render runs. The downloaded PNG carries the graph, so dropping it back reopens the graph.
 */

import { useState } from 'react';
import { LIMITS, type View } from '../../../nodes/core/scene.ts';
import type { PngExportOptions } from '../export.ts';
import { useModalDialog } from '../use-modal-dialog.ts';
import { ExportDialogShell, ExportRunFooter } from './ExportDialogShell.tsx';
import { useExportRun } from './use-export-run.ts';

export interface Size {
  readonly width: number;
  readonly height: number;
}

interface Props {
  /** The live render's size in css pixels (the "view size" preset). */
  readonly viewSize: Size;
  readonly view: View;
  readonly defaultSamples: number;
  /** The tile's edge width in pixels (0: no edges), to say how the export widens it. */
  readonly edgeWidth: number;
  /** Renders and downloads; resolves false when cancelled. `onProgress` returning false cancels. */
  run(o: PngExportOptions, onProgress: (f: number) => boolean): Promise<boolean>;
  onClose(): void;
}

const MAX = LIMITS.maxImageSide;
const PRESETS: readonly { label: string; size?: Size }[] = [
  { label: 'View size' },
  { label: '1920 × 1080 (Full HD)', size: { width: 1920, height: 1080 } },
  { label: '3840 × 2160 (4K)', size: { width: 3840, height: 2160 } },
  { label: '4096 × 4096', size: { width: 4096, height: 4096 } },
  { label: '8192 × 8192 (print)', size: { width: 8192, height: 8192 } },
  { label: `${MAX} × ${MAX} (largest)`, size: { width: MAX, height: MAX } },
];

const clampInt = (v: number, lo: number, hi: number) => Math.min(hi, Math.max(lo, Math.round(v) || lo));

export function ExportDialog({ viewSize, view, defaultSamples, edgeWidth, run, onClose }: Props) {
  const dialog = useModalDialog(onClose);
  const [width, setWidth] = useState(Math.max(1, Math.round(viewSize.width)));
  const [height, setHeight] = useState(Math.max(1, Math.round(viewSize.height)));
  const [samples, setSamples] = useState(clampInt(defaultSamples, 1, LIMITS.maxSamples));
  const [transparent, setTransparent] = useState(false);
  const { progress, error, ...exportRun } = useExportRun(onClose);

  const preset = PRESETS.findIndex((p) => {
    const s = p.size ?? viewSize;
    return Math.round(s.width) === width && Math.round(s.height) === height;
  });
  const megabytes = Math.ceil((width * height * 4) / 2 ** 20);
  const busy = progress !== null;
  // Tile edges are sized in device pixels of the live view.
  const referenceHeight = viewSize.height * (window.devicePixelRatio || 1);
  const edgeFactor = height / referenceHeight;

  const start = async () => {
    await exportRun.start((onProgress) =>
      run({ width, height, samples, transparent, view, referenceHeight }, onProgress),
    );
  };
  const close = exportRun.close;

  return (
    <ExportDialogShell
      dialogRef={dialog.ref}
      title="Export PNG"
      lead={
        <>
          Rendered on the GPU in tiles at full quality. The graph travels inside the file: drop the PNG onto
          Kleinflow to reopen it.
        </>
      }
      onClose={close}
    >
      <div className="kf-export__grid">
        <label htmlFor="kf-export-preset">Size</label>
        <select
          id="kf-export-preset"
          value={preset}
          disabled={busy}
          onChange={(e) => {
            const s = PRESETS[Number(e.target.value)]?.size ?? viewSize;
            setWidth(Math.round(s.width));
            setHeight(Math.round(s.height));
          }}
        >
          {preset === -1 && <option value={-1}>Custom</option>}
          {PRESETS.map((p, i) => (
            <option key={p.label} value={i}>
              {p.size
                ? p.label
                : `${p.label} (${Math.round(viewSize.width)} × ${Math.round(viewSize.height)})`}
            </option>
          ))}
        </select>
        <span className="kf-export__dims">
          <input
            type="number"
            aria-label="Width in pixels"
            min={1}
            max={MAX}
            value={width}
            disabled={busy}
            onChange={(e) => setWidth(clampInt(Number(e.target.value), 1, MAX))}
          />
          ×
          <input
            type="number"
            aria-label="Height in pixels"
            min={1}
            max={MAX}
            value={height}
            disabled={busy}
            onChange={(e) => setHeight(clampInt(Number(e.target.value), 1, MAX))}
          />
          <span className="kf-export__note">px · about {megabytes} MB of memory</span>
        </span>
        <label htmlFor="kf-export-samples">Samples</label>
        <span>
          <input
            id="kf-export-samples"
            type="number"
            min={1}
            max={LIMITS.maxSamples}
            value={samples}
            disabled={busy}
            onChange={(e) => setSamples(clampInt(Number(e.target.value), 1, LIMITS.maxSamples))}
          />
          <span className="kf-export__note"> per pixel (more: smoother, slower)</span>
        </span>
        <span>Background</span>
        <span className="kf-export__radios" role="radiogroup" aria-label="Background">
          <label>
            <input
              type="radio"
              name="kf-bg"
              checked={!transparent}
              disabled={busy}
              onChange={() => setTransparent(false)}
            />
            Solid
          </label>
          <label>
            <input
              type="radio"
              name="kf-bg"
              checked={transparent}
              disabled={busy}
              onChange={() => setTransparent(true)}
            />
            Transparent
          </label>
        </span>
      </div>
      {edgeWidth > 0 && Math.abs(edgeFactor - 1) > 0.01 && (
        <p className="kf-export__note">
          Tile edges are drawn {(edgeWidth * edgeFactor).toFixed(1)} px wide ({edgeWidth} px ×{' '}
          {edgeFactor.toFixed(2)}) so the picture looks like the view.
        </p>
      )}
      <ExportRunFooter
        progress={progress}
        progressText={(progress) =>
          progress < 1 ? `Rendering… ${Math.round(progress * 100)}%` : 'Encoding the PNG…'
        }
        error={error}
        startLabel={`Export ${width} × ${height}`}
        onStart={() => void start()}
        onCancel={exportRun.cancel}
        onClose={close}
      />
    </ExportDialogShell>
  );
}
