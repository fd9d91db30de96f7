import { readFileSync } from 'node:fs';
import { join } from 'node:path';
import { describe, expect, it } from 'vitest';
import { parseXml } from '../support/xml.ts';
import { cliTempDir, example, runCli, runCliOk } from './run-cli.ts';

const dir = cliTempDir('kleinflow-svg-');

describe('kleinflow svg', () => {
  it('writes the circles of the Apollonian gasket and says how many', () => {
    const out = join(dir, 'gasket.svg');
    const r = runCliOk([
      'svg',
      example('apollonian-gasket'),
      '--out',
      out,
      '--size',
      '400x300',
      '--min-radius',
      '2',
    ]);
    const said = /(\d+) edges and (\d+) seed disks/.exec(r.stdout);
    expect(said).not.toBeNull();
    const doc = parseXml(readFileSync(out, 'utf8'));
    expect(doc.documentElement.getAttribute('width')).toBe('400');
    const drawn = doc.documentElement.querySelectorAll(':scope > g circle, :scope > g line').length;
    expect(drawn).toBe(Number(said?.[1]) + Number(said?.[2]));
    expect(drawn).toBeGreaterThan(500);
  });

  it('names the node that prevents a vector export', () => {
    const r = runCli(['svg', example('glide-reflection-frieze'), '--out', join(dir, 'frieze.svg')]);
    expect(r.status).toBe(1);
    expect(r.stderr).toMatch(/no vector export: node "[^"]+" is a glide-reflection fold/);
  });

  it('rejects a bad minimum radius and a missing output with the usage', () => {
    const bad = runCli([
      'svg',
      example('schottky-pair'),
      '--out',
      join(dir, 'x.svg'),
      '--min-radius',
      'zero',
    ]);
    expect(bad.status).toBe(2);
    expect(bad.stderr).toContain('--min-radius expects a positive number');
    const missing = runCli(['svg', example('schottky-pair')]);
    expect(missing.status).toBe(2);
    expect(missing.stderr).toContain('missing --out');
  });
});
