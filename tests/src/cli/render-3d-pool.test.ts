/**
 * A 3D still split into bands over worker threads is byte for byte the single-threaded render
 * (any band size, any thread count), and a band that fails is reported with its rows.
 */
import { describe, expect, it } from 'vitest';
import { renderScene3d } from '../../../shader-gen/space/render-3d.ts';
import { CliError } from '../../../src/cli/command.ts';
import { bandRows, bandsOf, renderScene3dOnPool } from '../../../src/cli/render-3d-pool.ts';
import { FIG11, LONE_SPHERE } from '../../shader-gen/space/scenes-3d.ts';

describe('bands of a 3D still', () => {
  it('cover every row once, in order, whatever their size', () => {
    for (const [height, rows] of [
      [17, 1],
      [17, 3],
      [17, 17],
      [17, 40],
    ] as const) {
      const bands = bandsOf(height, rows);
      expect(bands[0]?.start).toBe(0);
      expect(bands.at(-1)?.end).toBe(height);
      for (let i = 1; i < bands.length; i++) expect(bands[i]?.start).toBe(bands[i - 1]?.end);
    }
  });

  it('are small enough for progress every second and for every thread to find work', () => {
    expect(bandRows(1024, 2, 0.1)).toBe(10); // one second of one thread
    expect(bandRows(1024, 2, 0.001)).toBe(64); // 8 bands per thread at least
    expect(bandRows(1024, 2, 5)).toBe(1); // a row of more than a second: one row each
    expect(bandRows(3, 8)).toBe(1);
  });
});

describe('renderScene3dOnPool', () => {
  it('gives the bytes of the single-threaded render', async () => {
    const [width, height, samples] = [23, 17, 2];
    const one = renderScene3d(FIG11, width, height, { samples });
    // The picture has surface and sky, so a misplaced band would show.
    expect(new Set(new Uint32Array(one.data.buffer)).size).toBeGreaterThan(10);
    for (const threads of [2, 3]) {
      const fractions: number[] = [];
      const onProgress = (f: number) => void fractions.push(f);
      const many = await renderScene3dOnPool(FIG11, { width, height, samples, threads, onProgress });
      expect(Buffer.from(many.data)).toEqual(Buffer.from(one.data));
      // Bands of the balanced size (1 row for 3 threads, 2 for 2), progress after each.
      expect(fractions.length).toBe(bandsOf(height, bandRows(height, threads)).length);
      expect(fractions.at(-1)).toBe(1);
    }
  }, 60_000);

  it('reports a band that fails on a worker thread with its rows and the reason', async () => {
    const broken = { ...LONE_SPHERE, camera: null as never };
    const run = renderScene3dOnPool(broken, { width: 8, height: 6, samples: 1, threads: 2 });
    await expect(run).rejects.toBeInstanceOf(CliError);
    await expect(run).rejects.toThrow(
      /^the 3D render failed on a worker thread: rows \d+–\d+: Cannot read properties of null/,
    );
  });
});
