import { readFileSync } from 'node:fs';
import { join } from 'node:path';
import { describe, expect, it } from 'vitest';
import { decodePng } from '../../src/io/png.ts';
import { parseXml } from '../support/xml.ts';
import { cliTempDir, example, runCli, runCliOk } from './run-cli.ts';

const dir = cliTempDir('kleinflow-figures-');

describe('kleinflow figures (Cayley graph, depth-first limit set)', () => {
  it('svg writes the depth-first limit set over the tiling and counts it', () => {
    const out = join(dir, 'dfs.svg');
    const r = runCliOk(['svg', example('fig05-limit-set-depth-first'), '--out', out, '--size', '300x300']);
    const said = /, (\d+) figure strokes and points/.exec(r.stdout);
    expect(said).not.toBeNull();
    const figures = parseXml(readFileSync(out, 'utf8')).querySelector('g.figures');
    const drawn =
      (figures?.querySelectorAll('polyline').length ?? 0) + (figures?.querySelectorAll('circle').length ?? 0);
    expect(drawn).toBe(Number(said?.[1]));
    expect(drawn).toBeGreaterThan(20);
  });

  it('render paints the Cayley graph into the PNG: the base point is a white dot', () => {
    const out = join(dir, 'cayley.png');
    const r = runCli([
      'render',
      example('fig01-cayley-graph'),
      '-o',
      out,
      '--size',
      '200x200',
      '--samples',
      '1',
    ]);
    expect(r.status).toBe(0);
    const png = decodePng(readFileSync(out));
    // Find the whitest pixel near the view centre (the base point sits in the hole of the ring).
    let white = 0;
    for (let y = 80; y < 130; y++)
      for (let x = 75; x < 125; x++) {
        const o = (y * png.width + x) * 4;
        if (png.data[o] === 255 && png.data[o + 1] === 255 && png.data[o + 2] === 255) white++;
      }
    expect(white).toBeGreaterThan(10);
  });
});
