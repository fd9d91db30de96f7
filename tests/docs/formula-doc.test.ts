/** docs/formula.md lists every function and constant the language has, and no others. */
import { readFileSync } from 'node:fs';
import { describe, expect, it } from 'vitest';
import { CONSTANTS, FUNCTIONS } from '../../nodes/formula/functions.ts';
import { FORMULA_NAMES } from '../../nodes/formula/names.ts';

const text = readFileSync(new URL('../../docs/formula.md', import.meta.url), 'utf8');
const section = (title: string) => text.split(`## ${title}\n`)[1]!.split('\n## ')[0]!;

describe('docs/formula.md', () => {
  it('lists exactly the functions of nodes/formula/functions.ts', () => {
    const listed = new Set([...section('Functions').matchAll(/`(\w+)\(/g)].map((m) => m[1]));
    expect([...listed].sort()).toEqual(Object.keys(FUNCTIONS).sort());
  });

  it('lists exactly the names and constants a formula may use', () => {
    const listed = new Set([...section('Names').matchAll(/`(\w+)`/g)].map((m) => m[1]));
    expect([...listed].sort()).toEqual([...Object.keys(FORMULA_NAMES), ...Object.keys(CONSTANTS)].sort());
  });
});
