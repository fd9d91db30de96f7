import fc from 'fast-check';
import { deflateSync } from 'fflate';
import { describe, expect, it } from 'vitest';
import { LIMITS } from '../../../nodes/core/scene.ts';
import { emptyDocument, type GraphDoc } from '../../../nodes/graph/document.ts';
import { parseDocumentText } from '../../../nodes/graph/load.ts';
import { registry } from '../../../nodes/types/index.ts';
import { decodeBase64Url, encodeBase64Url } from '../../../src/io/base64url.ts';
import { boundedInflate, decodeShareFragment, encodeShareFragment } from '../../../src/io/share-url.ts';
import { exampleFiles } from './support/examples.ts';

const load = (text: string): GraphDoc => {
  const r = parseDocumentText(text, registry);
  if (!r.ok) throw new Error(r.diagnostics.map((d) => d.message).join('\n'));
  return r.doc;
};
const fragmentOf = (doc: GraphDoc): string => {
  const r = encodeShareFragment(doc);
  if (!r.ok) throw new Error(r.message);
  return r.fragment;
};
const messageOf = (fragment: string): string => {
  const r = decodeShareFragment(fragment);
  if (r.ok) throw new Error('expected a failure');
  return r.message;
};
const bytesFragment = (bytes: Uint8Array) => `#g=${encodeBase64Url(bytes)}`;

describe('share links', () => {
  for (const { name, text } of exampleFiles()) {
    it(`${name} survives encode → decode unchanged`, () => {
      const doc = load(text);
      const fragment = fragmentOf(doc);
      expect(fragment).toMatch(/^#g=[A-Za-z0-9_-]+$/);
      const back = decodeShareFragment(fragment);
      expect(back.ok && back.doc).toEqual(doc);
    });
  }

  it('accepts the whole URL, and other fragment parameters beside g', () => {
    const doc = load(exampleFiles()[0].text);
    const payload = fragmentOf(doc).slice(1);
    for (const text of [`https://kleinflow.example/app/#${payload}`, `#view=1&${payload}&x=2`, payload]) {
      const r = decodeShareFragment(text);
      expect(r.ok && r.doc).toEqual(doc);
    }
  });

  it('rejects a zip bomb (50 MB of zeros) with a message, stopping just past the cap', () => {
    const bomb = deflateSync(new Uint8Array(50 * 1024 * 1024), { level: 9 });
    const fragment = bytesFragment(bomb);
    expect(fragment.length).toBeLessThan(LIMITS.shareFragmentMaxChars);
    const t = performance.now();
    expect(messageOf(fragment)).toMatch(/unpacks to more than 4194304 bytes/);
    // Generous for a loaded machine; inflating all 50 MB takes several times longer.
    expect(performance.now() - t).toBeLessThan(2000);
    // The work is bounded, not just the answer: inflation stopped within ~1 MB past the cap.
    const r = boundedInflate(bomb, LIMITS.shareInflatedMaxBytes);
    expect(r.ok).toBe(false);
    if (!r.ok) {
      expect(r.inflated).toBeGreaterThan(LIMITS.shareInflatedMaxBytes);
      expect(r.inflated).toBeLessThan(LIMITS.shareInflatedMaxBytes + 1.1 * 1024 * 1024);
    }
  });

  it('refuses a fragment over the size cap before decoding it', () => {
    const message = messageOf(`#g=${'A'.repeat(LIMITS.shareFragmentMaxChars + 1)}`);
    expect(message).toMatch(/too long \(524289 characters; the limit is 524288\)/);
  });

  it('refuses to make a link for a graph over the cap, with a message', () => {
    // Random labels do not compress: enough of them make the link too long.
    const doc = emptyDocument('huge');
    let seed = 1;
    const noise = () => {
      seed = (seed * 1103515245 + 12345) % 2 ** 31;
      return seed.toString(36);
    };
    doc.nodes = Array.from({ length: 4000 }, (_, i) => ({
      id: `n${i}`,
      type: 'number',
      position: [i, 0] as [number, number],
      params: { value: i },
      label: Array.from({ length: 40 }, noise).join('').slice(0, 190),
    }));
    const r = encodeShareFragment(doc);
    expect(r.ok).toBe(false);
    if (!r.ok) expect(r.message).toMatch(/too large for a share link .* save it as a file instead/);
  });

  it('explains truncated, garbled and foreign fragments', () => {
    const good = fragmentOf(load(exampleFiles()[0].text));
    expect(messageOf(good.slice(0, Math.floor(good.length / 2)))).toMatch(/cut off when copied/);
    expect(messageOf(`${good.slice(0, 20)}!${good.slice(21)}`)).toMatch(
      /character "!" at position 17 is not base64url/,
    );
    expect(messageOf('#g=')).toMatch(/empty/);
    expect(messageOf('#view=2')).toMatch(/no "#g=" part/);
    expect(messageOf(bytesFragment(new TextEncoder().encode('hello, not deflate at all')))).toMatch(
      /damaged|cut off/,
    );
    expect(messageOf(bytesFragment(deflateSync(new TextEncoder().encode('{"nodes": ['))))).toMatch(
      /does not hold a graph/,
    );
    expect(messageOf(bytesFragment(deflateSync(new TextEncoder().encode('{"format":"kleinflow"}'))))).toMatch(
      /graph cannot be opened: version/,
    );
  });

  it('base64url round-trips any bytes and rejects impossible lengths', () => {
    fc.assert(
      fc.property(fc.uint8Array({ maxLength: 300 }), (bytes) => {
        const text = encodeBase64Url(bytes);
        expect(text).toMatch(/^[A-Za-z0-9_-]*$/);
        const back = decodeBase64Url(text);
        expect(back.ok && [...back.bytes]).toEqual([...bytes]);
      }),
      { seed: 42, numRuns: 300 },
    );
    expect(decodeBase64Url('abcde').ok).toBe(false);
    expect(encodeBase64Url(new TextEncoder().encode('Man'))).toBe('TWFu');
    expect(encodeBase64Url(Uint8Array.from([0xfb, 0xff]))).toBe('-_8');
  });
});
