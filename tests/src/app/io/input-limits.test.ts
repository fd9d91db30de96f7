/** The editor's input limits: an oversized paste is refused in one line before it is parsed. */
import { describe, expect, it } from 'vitest';
import { openPastedText } from '../../../../src/app/io/pasted-document.ts';
import { INPUT_LIMITS } from '../../../../src/io/input-limits.ts';

describe('pasted text past the limit', () => {
  it('a graph-like paste over the limit is refused with the limit named; other text is not ours', () => {
    const huge = `{"format":"kleinflow","meta":{"title":"${'x'.repeat(INPUT_LIMITS.documentBytes)}"}}`;
    const r = openPastedText(huge);
    expect(r?.ok).toBe(false);
    expect(r && !r.ok && r.diagnostics[0].message).toMatch(/more than 64 MB, the limit for a graph/);
    expect(openPastedText('y'.repeat(INPUT_LIMITS.documentBytes + 1))).toBeNull();
  });
});
