/**
 * The README's table of the paper's figures ("The paper's figures") names real examples: every
 * example id in it (a code span; `-warm` style suffixes extend the id before them) is a file in
 * examples/ or examples/3d/, every figure 1–44 has a row, and a ✓ row names at least one example
 * or a tool.
 */
import { readFileSync } from 'node:fs';
import { join } from 'node:path';
import { describe, expect, it } from 'vitest';
import { EXAMPLES_3D_DIR, exampleNames } from '../../src/cli/examples.ts';

const README = readFileSync(join(import.meta.dirname, '..', '..', 'README.md'), 'utf8');
const section = README.slice(README.indexOf("### The paper's figures"));
const rows = section
  .slice(0, section.indexOf('\n\n', section.indexOf('| Fig.')))
  .split('\n')
  .filter((l) => /^\| \d/.test(l));

/**
 * Example ids of a row: `name`, and a `-suffix` after it as that name with its last segments (as
 * many as the suffix has) replaced: `fig34-…-by-inversions`, `-by-distance` → `fig34-…-by-distance`.
 */
function idsOf(row: string): string[] {
  const ids: string[] = [];
  let base: string | null = null;
  for (const [, span] of row.matchAll(/`([^`]+)`/g)) {
    if (/^-[a-z0-9-]+$/.test(span) && base) {
      const keep = base.split('-').slice(0, -(span.split('-').length - 1));
      ids.push(`${keep.join('-')}${span}`);
    } else if (/^[a-z0-9]+(-[a-z0-9]+)*$/.test(span)) {
      base = span;
      ids.push(span);
    }
  }
  return ids;
}

describe("README: the paper's figures", () => {
  const names = new Set([...exampleNames(), ...exampleNames(EXAMPLES_3D_DIR)]);

  it('has a row for every figure 1–44', () => {
    const covered = new Set<number>();
    for (const row of rows) {
      const [from, to] = row
        .match(/^\| (\d+)(?:–(\d+))?/)!
        .slice(1)
        .map(Number);
      for (let k = from!; k <= (to || from)!; k++) covered.add(k);
    }
    expect([...Array(44)].map((_, i) => i + 1).filter((k) => !covered.has(k))).toEqual([]);
  });

  it('names only examples that exist', () => {
    const ids = rows.flatMap(idsOf);
    expect(ids.length).toBeGreaterThan(40);
    expect(ids.filter((id) => !names.has(id))).toEqual([]);
  });

  it('a reproduced (✓) figure names an example, a command or a tool', () => {
    for (const row of rows.filter((r) => r.trimEnd().endsWith('✓ |')))
      expect(idsOf(row).length > 0 || /kleinflow|Inspect|Export/.test(row), row).toBe(true);
  });
});
