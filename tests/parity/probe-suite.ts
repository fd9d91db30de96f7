/**
 * The set-up the 3D parity files share: one GpuProbe of width × height for the file, opened before
 * its tests and handed to `use`; after them the rows the tests filled are printed as one table
 * headed `title`, and the probe is closed. With `skip` nothing is opened (an opt-in file).
 */
import { afterAll, beforeAll } from 'vitest';
import { GpuProbe } from './gpu-probe.ts';

export type ParityRows = Record<string, Record<string, string | number>>;

export function probeForSuite(
  width: number,
  height: number,
  title: string,
  use: (gpu: GpuProbe) => void,
  options: { readonly skip?: boolean } = {},
): ParityRows {
  const rows: ParityRows = {};
  let gpu: GpuProbe | undefined;
  beforeAll(async () => {
    if (options.skip) return;
    gpu = await GpuProbe.open(width, height);
    use(gpu);
  });
  afterAll(async () => {
    if (options.skip) return;
    console.log(`\n${title} (${width}×${height}, SwiftShader):`);
    console.table(rows);
    await gpu?.close();
  });
  return rows;
}
