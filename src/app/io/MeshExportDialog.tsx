/**
 * The mesh export dialog (3D printing, paper §5.3.2 and Fig. 36): the format (STL, or 3MF / GLB with
 * the render's colours), voxel resolution, an optional box and an optional print size (the longest
 * side in mm; empty: one scene unit = 1 mm, src/io/print-size.ts); a progress bar with Cancel while the
 * solid is sampled and meshed on the CPU. The mesh is closed and consistently oriented in every
 * format (docs/math-3d.md "Voxel mesh (paper §5.3.2)", "Coloured mesh (paper Fig. 36)").
 */

import { useState } from 'react';
import {
  type Bounds3,
  MAX_MESH_RESOLUTION,
  MIN_MESH_RESOLUTION,
  parseBounds,
} from '../../../nodes/geometry/space/voxel-mesh.ts';
import { MESH_FORMATS, type MeshFormat } from '../../io/mesh-file.ts';
import { MAX_PRINT_SIZE_MM, MIN_PRINT_SIZE_MM, parsePrintSize } from '../../io/print-size.ts';
import { useModalDialog } from '../use-modal-dialog.ts';
import { ExportDialogShell, ExportRunFooter } from './ExportDialogShell.tsx';
import { useExportRun } from './use-export-run.ts';

export interface MeshExportOptions {
  readonly format: MeshFormat;
  readonly resolution: number;
  readonly bounds?: Bounds3;
  /** The longest side in millimetres; absent: one scene unit is 1 mm. */
  readonly printSize?: number;
}

interface Props {
  /** Meshes and downloads; resolves false when cancelled. `onProgress` returning false cancels. */
  run(o: MeshExportOptions, onProgress: (f: number) => boolean): Promise<boolean>;
  onClose(): void;
}

export const DEFAULT_MESH_RESOLUTION = 64;
/** The coloured formats' progress bar: meshing up to here, then colouring the vertices. */
export const MESHING_SHARE = 0.6;

const FORMATS = Object.keys(MESH_FORMATS) as MeshFormat[];

export function MeshExportDialog({ run, onClose }: Props) {
  const dialog = useModalDialog(onClose);
  const [format, setFormat] = useState<MeshFormat>('stl');
  const [resolution, setResolution] = useState(DEFAULT_MESH_RESOLUTION);
  const [boundsText, setBoundsText] = useState('');
  const [printSizeText, setPrintSizeText] = useState('');
  const { progress, error, ...exportRun } = useExportRun(onClose);
  const busy = progress !== null;
  const bounds = boundsText.trim() === '' ? null : parseBounds(boundsText);
  const printSize = printSizeText.trim() === '' ? null : parsePrintSize(printSizeText);
  const inputError =
    bounds && !bounds.ok
      ? `Bounds: ${bounds.error}`
      : printSize && !printSize.ok
        ? `Print size: ${printSize.error}`
        : null;

  const start = async () => {
    if ((bounds && !bounds.ok) || (printSize && !printSize.ok)) return;
    await exportRun.start((onProgress) =>
      run(
        {
          format,
          resolution,
          ...(bounds?.ok ? { bounds: bounds.value } : {}),
          ...(printSize?.ok ? { printSize: printSize.value } : {}),
        },
        onProgress,
      ),
    );
  };
  const close = exportRun.close;

  return (
    <ExportDialogShell
      dialogRef={dialog.ref}
      title="Export mesh"
      lead={
        <>
          A closed mesh of the solid (the seeds’ orbit) for 3D printing, sampled on a voxel grid on the CPU.
          3MF and GLB carry the render’s colouring at every vertex, unlit, for full-colour printers and
          viewers.
        </>
      }
      onClose={close}
    >
      <div className="kf-export__grid">
        <label htmlFor="kf-mesh-format">Format</label>
        <span>
          <select
            id="kf-mesh-format"
            value={format}
            disabled={busy}
            onChange={(e) => setFormat(e.target.value as MeshFormat)}
          >
            {FORMATS.map((f) => (
              <option key={f} value={f}>
                {MESH_FORMATS[f].label}
              </option>
            ))}
          </select>
        </span>
        <label htmlFor="kf-mesh-resolution">Resolution</label>
        <span>
          <input
            id="kf-mesh-resolution"
            type="number"
            min={MIN_MESH_RESOLUTION}
            max={MAX_MESH_RESOLUTION}
            value={resolution}
            disabled={busy}
            onChange={(e) =>
              setResolution(
                Math.min(
                  MAX_MESH_RESOLUTION,
                  Math.max(MIN_MESH_RESOLUTION, Math.round(Number(e.target.value)) || 0),
                ),
              )
            }
          />
          <span className="kf-export__note"> voxels along the longest side (time grows with its cube)</span>
        </span>
        <label htmlFor="kf-mesh-bounds">Box</label>
        <span>
          <input
            id="kf-mesh-bounds"
            type="text"
            placeholder="auto"
            value={boundsText}
            disabled={busy}
            onChange={(e) => setBoundsText(e.target.value)}
          />
          {/* The format in the note, not the placeholder: a field that narrow cut it off. */}
          <span className="kf-export__note">
            {' '}
            x0, y0, z0, x1, y1, z1 — needed when plane mirrors repeat the solid without end
          </span>
        </span>
        <label htmlFor="kf-mesh-print-size">Print size</label>
        <span>
          <input
            id="kf-mesh-print-size"
            type="text"
            inputMode="decimal"
            placeholder="1 unit = 1 mm"
            value={printSizeText}
            disabled={busy}
            aria-describedby="kf-mesh-print-size-note"
            onChange={(e) => setPrintSizeText(e.target.value)}
          />
          <span id="kf-mesh-print-size-note" className="kf-export__note">
            {' '}
            mm, the longest side ({MIN_PRINT_SIZE_MM}…{MAX_PRINT_SIZE_MM}); empty: one scene unit is 1 mm. GLB
            stores the same size in metres.
          </span>
        </span>
      </div>
      <ExportRunFooter
        progress={progress}
        progressText={(progress) =>
          progress >= 1
            ? `Writing the ${format.toUpperCase()}…`
            : MESH_FORMATS[format].coloured && progress >= MESHING_SHARE
              ? `Colouring the vertices… ${Math.round(progress * 100)}%`
              : `Meshing… ${Math.round(progress * 100)}%`
        }
        error={inputError ?? error}
        startLabel={`Export ${format.toUpperCase()} ${resolution}³${printSize?.ok ? `, ${printSize.value} mm` : ''}`}
        startDisabled={inputError !== null}
        onStart={() => void start()}
        onCancel={exportRun.cancel}
        onClose={close}
      />
    </ExportDialogShell>
  );
}
