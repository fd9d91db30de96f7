/**
 * What the benchmarks share when they report: the median of a sample and a plain-text table.
 * No Node or DOM imports: gpu-page.ts (bundled into the browser) uses the median too.
 */

/** Width and height in pixels of every frame the GPU benches draw. */
export const FRAME_SIZE = 512;

/** The median (the mean of the middle two for an even count). */
export function median(xs: readonly number[]): number {
  const s = [...xs].sort((a, b) => a - b);
  return s.length % 2 ? s[(s.length - 1) / 2] : (s[s.length / 2 - 1] + s[s.length / 2]) / 2;
}

/**
 * The median of the per-round ratios a[r] / b[r] of two interleaved series: each round's frames ran
 * under the same machine load, so this is steadier than the ratio of the medians.
 */
export function medianRatio(a: readonly number[], b: readonly number[]): number {
  return median(a.map((x, r) => x / b[r]));
}

/** Prints a header, a rule and the rows: the first column left-aligned, the others right-aligned. */
export function printTable(header: readonly string[], rows: readonly string[][]): void {
  const widths = header.map((h, i) => Math.max(h.length, ...rows.map((r) => r[i].length)));
  const line = (cells: readonly string[]) =>
    cells.map((c, i) => (i === 0 ? c.padEnd(widths[i]) : c.padStart(widths[i]))).join('  ');
  console.log(line(header));
  console.log(widths.map((w) => '-'.repeat(w)).join('  '));
  for (const r of rows) console.log(line(r));
}
