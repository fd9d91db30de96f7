/**
 * The presentation's text in the document: step notes round-trip through the file and the share
 * link, their limits are enforced with a clear message, and the present link / embed snippet are
 * well-formed with the title escaped.
 */
import { describe, expect, it } from 'vitest';
import { NOTE_MAX_CHARS, NOTES_MAX } from '../../../../nodes/graph/document.ts';
import { loadDocument, parseDocumentText } from '../../../../nodes/graph/load.ts';
import { registry } from '../../../../nodes/types/index.ts';
import { escapeAttribute, presentLinks } from '../../../../src/app/present/present-link.ts';
import { serializeDocument } from '../../../../src/io/json-text.ts';
import { decodeShareFragment } from '../../../../src/io/share-url.ts';
import { doc, node } from '../../../nodes/support/doc.ts';

const where = { origin: 'https://kf.example', pathname: '/app/' };
const withNotes = (stepNotes: Record<string, string>, title = 'Mirrors') => ({
  ...doc([node('p1', 'point', { x: 0, y: 0 }), node('out', 'render')], []),
  meta: { title, description: 'A **lesson**', stepNotes },
});

describe('presentation text in the document', () => {
  it('round-trips step notes through the saved file and the share link', () => {
    const d = withNotes({ p1: 'The first **point**.\n\n- and a list', out: '<b>not html</b>' });
    const saved = parseDocumentText(serializeDocument(d), registry);
    if (!saved.ok) throw new Error(JSON.stringify(saved.diagnostics));
    expect(saved.doc.meta).toEqual(d.meta);
    const links = presentLinks(d, where);
    if (!links.ok) throw new Error(links.message);
    const shared = decodeShareFragment(links.present.slice(links.present.indexOf('#')));
    if (!shared.ok) throw new Error(shared.message);
    expect(shared.doc.meta).toEqual(d.meta);
  });

  it('refuses a note over the limit, too many notes, or a note that is not text, saying where', () => {
    const long = loadDocument(withNotes({ p1: 'x'.repeat(NOTE_MAX_CHARS + 1) }), registry);
    expect(long.ok).toBe(false);
    expect(long.diagnostics.map((d) => d.message).join('\n')).toMatch(/meta\.stepNotes\.p1.*5000 characters/);
    const many = Object.fromEntries(Array.from({ length: NOTES_MAX + 1 }, (_, i) => [`n${i}`, 'x']));
    const tooMany = loadDocument(withNotes(many), registry);
    expect(tooMany.ok).toBe(false);
    expect(tooMany.diagnostics.map((d) => d.message).join('\n')).toMatch(/at most 500 step notes/);
    expect(loadDocument(withNotes({ p1: 3 } as never), registry).ok).toBe(false);
    expect(loadDocument(withNotes({ p1: 'x'.repeat(NOTE_MAX_CHARS) }), registry).ok).toBe(true);
  });
});

describe('present link and embed snippet', () => {
  it('point at the read-only presentation with the graph in the fragment', () => {
    const links = presentLinks(withNotes({}), where);
    if (!links.ok) throw new Error(links.message);
    expect(links.present).toMatch(/^https:\/\/kf\.example\/app\/\?mode=present#g=/);
    expect(links.embed).toBe(
      `<iframe src="${links.present}" title="Mirrors" width="800" height="500" style="border:0" allow="fullscreen"></iframe>`,
    );
  });

  it('escape the title inside the snippet so it cannot close the attribute', () => {
    const links = presentLinks(withNotes({}, '"><script>alert(1)</script>'), where);
    if (!links.ok) throw new Error(links.message);
    expect(links.embed).not.toContain('<script>');
    expect(links.embed).toContain('title="&quot;&gt;&lt;script&gt;alert(1)&lt;/script&gt;"');
    expect(escapeAttribute('a & "b" <c>')).toBe('a &amp; &quot;b&quot; &lt;c&gt;');
  });
});
