/**
 * Every example (plane and space) has a gallery thumbnail rendered by the CLI from the example's current file:
 * thumbs/sources.json records the SHA-256 of the file each thumbnail shows, so editing an example
 * without re-rendering its thumbnail fails here (fix: npm run render-examples -- --thumbnails).
 */
import { existsSync, readFileSync } from 'node:fs';
import { join } from 'node:path';
import { describe, expect, it } from 'vitest';
import { allExamples, EXAMPLES_THUMB_DIR, exampleDigest, THUMB_SOURCES } from '../../src/cli/examples.ts';
import { THUMB } from '../../src/cli/render-examples.ts';

/** Width and height from a PNG's IHDR chunk (bytes 16–23, big-endian). */
function pngSize(bytes: Buffer): { width: number; height: number } {
  expect(bytes.subarray(1, 4).toString('latin1')).toBe('PNG');
  return { width: bytes.readUInt32BE(16), height: bytes.readUInt32BE(20) };
}

describe('example thumbnails', () => {
  const sources = JSON.parse(readFileSync(THUMB_SOURCES, 'utf8')) as Record<string, string>;

  const examples = allExamples();
  it.each(examples.map((e) => [e.name, e.dir]))('%s has a current thumbnail', (name, dir) => {
    const file = join(EXAMPLES_THUMB_DIR, `${name}.png`);
    expect(existsSync(file), `${file} is missing: npm run render-examples -- --thumbnails ${name}`).toBe(
      true,
    );
    expect(pngSize(readFileSync(file))).toEqual({ width: THUMB.width, height: THUMB.height });
    expect(sources[name], `stale thumbnail: npm run render-examples -- --thumbnails ${name}`).toBe(
      exampleDigest(name, dir),
    );
  });

  it('records no thumbnail of an example that is gone', () => {
    expect(Object.keys(sources).sort()).toEqual(examples.map((e) => e.name).sort());
  });
});
