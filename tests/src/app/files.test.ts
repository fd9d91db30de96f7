/** A dropped or chosen file that breaks a limit is reported to the user in one line, never thrown. */
import { describe, expect, it } from 'vitest';
import { readDocumentFile } from '../../../src/app/files.ts';
import { openReport } from '../../../src/app/io/open-report.ts';
import { INPUT_LIMITS } from '../../../src/io/input-limits.ts';
import { pngChunk, pngWith, textData } from '../io/support/png-chunks.ts';

const dropped = (bytes: Uint8Array, name: string) =>
  new File([new Uint8Array(bytes)], name, { type: 'image/png' });

describe('a dropped PNG past the PNG limits', () => {
  it('a 2 MB text keyword: an error report (KF504) naming the keyword limit, not a page error', async () => {
    const keyword = new Uint8Array(2 * 1024 * 1024).fill(0x41);
    const file = dropped(pngWith([pngChunk('tEXt', textData(keyword, 'x'))]), 'long-keyword.png');
    const result = await readDocumentFile(file);
    expect(result.ok).toBe(false);
    const report = openReport('“long-keyword.png”', result);
    expect(report?.kind).toBe('error');
    expect(report?.items).toEqual([
      expect.objectContaining({ code: 'KF504', text: expect.stringMatching(/longer than 79 bytes/) }),
    ]);
  });

  it('more chunks than the limit: refused the same way', async () => {
    const tiny = pngChunk('tIME', new Uint8Array(7));
    const file = dropped(pngWith(Array.from({ length: INPUT_LIMITS.pngChunks + 1 }, () => tiny)), 'many.png');
    const result = await readDocumentFile(file);
    expect(!result.ok && result.diagnostics[0]).toMatchObject({ code: 'KF504' });
  });
});
