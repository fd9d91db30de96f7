import { readFileSync, writeFileSync } from 'node:fs';
import { describe, expect, it } from 'vitest';
import { registry } from '../../nodes/types/index.ts';
import {
  nodeReference,
  quickStart3dList,
  quickStartList,
  replaceSection,
  shortcutTable,
} from './readme-tables.ts';

const README = new URL('../../README.md', import.meta.url);

describe('README stays true to the code', () => {
  const text = readFileSync(README, 'utf8');
  const sections: [string, string][] = [
    ['nodes', nodeReference()],
    ['shortcuts', shortcutTable()],
    ['quickstart', quickStartList()],
    ['quickstart3d', quickStart3dList()],
  ];
  const expected = sections.reduce((t, [name, body]) => replaceSection(t, name, body), text);
  const updating = process.env.UPDATE_README === '1';
  if (updating && expected !== text) writeFileSync(README, expected);
  const final = updating ? expected : text;

  it('lists every registered node type with its one-line doc (run with UPDATE_README=1 to regenerate)', () => {
    expect(final).toBe(expected);
    for (const def of registry.all) expect(final).toContain(`| \`${def.type}\` |`);
  });

  it('shows the README commands a newcomer runs', () => {
    expect(final).toContain('npm install && npm start');
    expect(final).toContain('npm test');
  });
});
