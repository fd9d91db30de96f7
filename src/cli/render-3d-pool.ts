/**
 * A 3D still on every core: the image is cut into bands of whole rows, handed to worker threads
 * (src/cli/band-3d-job.ts, through the pool of `--frames`) as each one finishes its last, and
 * put back together by row. Pixels depend on nothing but their position (render-3d.ts), so the
 * result is byte for byte the single-threaded render. Bands are small, so progress comes often
 * and a slow band at the end leaves little waiting.
 */
import type { Scene3d } from '../../nodes/core/scene-3d.ts';
import { type Raster3d, renderScene3d } from '../../shader-gen/space/render-3d.ts';
import type { Band3d, Band3dResult, Band3dSetup } from './band-3d-job.ts';
import { CliError } from './command.ts';
import { runPool } from './worker-pool.ts';

export interface Pool3dRequest {
  readonly width: number;
  readonly height: number;
  readonly samples: number;
  /** Worker threads; 1 renders on this thread (no worker to start). */
  readonly threads: number;
  /** Single-thread seconds per row (from the estimate): sizes the bands. */
  readonly secondsPerRow?: number;
  /** The fraction done, after each band (each row on one thread). */
  readonly onProgress?: (fraction: number) => void;
}

/** A band should take about this long on one thread: progress at least this often per thread. */
const BAND_SECONDS = 1;
/** At least this many bands per thread, so threads that finish early find work left. */
const BANDS_PER_THREAD = 8;

/** Rows per band for `threads` threads at `secondsPerRow` (unknown: only the balance counts). */
export function bandRows(height: number, threads: number, secondsPerRow = 0): number {
  const balanced = Math.ceil(height / (threads * BANDS_PER_THREAD));
  const timely = secondsPerRow > 0 ? Math.floor(BAND_SECONDS / secondsPerRow) : balanced;
  return Math.max(1, Math.min(balanced, timely));
}

/** The bands of an image, top to bottom. */
export function bandsOf(height: number, rows: number): Band3d[] {
  const bands: Band3d[] = [];
  for (let start = 0; start < height; start += rows)
    bands.push({ start, end: Math.min(height, start + rows) });
  return bands;
}

export async function renderScene3dOnPool(scene: Scene3d, request: Pool3dRequest): Promise<Raster3d> {
  const { width, height, samples, threads, onProgress } = request;
  if (threads <= 1)
    return renderScene3d(scene, width, height, {
      samples,
      onProgress: onProgress && ((f) => void onProgress(f)),
    });
  const bands = bandsOf(height, bandRows(height, threads, request.secondsPerRow));
  const data = new Uint8ClampedArray(width * height * 4);
  const setup: Band3dSetup = { scene, width, height, samples };
  let rowsDone = 0;
  let failure: string | undefined;
  try {
    await runPool<Band3d, Band3dResult>(
      new URL('./band-3d-job.ts', import.meta.url),
      bands,
      threads,
      (r) => {
        if ('error' in r) {
          failure ??= `rows ${r.start}–${r.end - 1}: ${r.error}`;
          return false;
        }
        data.set(r.data, 4 * width * r.start);
        rowsDone += r.end - r.start;
        onProgress?.(rowsDone / height);
        return true;
      },
      { workerData: setup },
    );
  } catch (e) {
    failure ??= e instanceof Error ? e.message : String(e);
  }
  if (failure !== undefined) throw new CliError(`the 3D render failed on a worker thread: ${failure}`);
  return { width, height, data };
}
