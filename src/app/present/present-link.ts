/**
 * The classroom's links: the presentation's address (`?mode=present#g=…`, read-only, opens at step
 * 1) and an iframe snippet for a class page. The graph travels in the fragment (src/io/share-url.ts).
 */
import type { GraphDoc } from '../../../nodes/graph/document.ts';
import { shareLinkFor } from '../io/share-link.ts';

export type PresentLinks = { ok: true; present: string; embed: string } | { ok: false; message: string };

/** Text made safe inside a double-quoted HTML attribute. */
export function escapeAttribute(text: string): string {
  return text.replace(/&/g, '&amp;').replace(/"/g, '&quot;').replace(/</g, '&lt;').replace(/>/g, '&gt;');
}

export function presentLinks(doc: GraphDoc, where: Pick<Location, 'origin' | 'pathname'>): PresentLinks {
  const link = shareLinkFor(doc, where);
  if (!link.ok) return link;
  const hash = link.url.indexOf('#');
  const at = (mode: string) => `${link.url.slice(0, hash)}?mode=${mode}${link.url.slice(hash)}`;
  const present = at('present');
  const title = escapeAttribute(doc.meta.title?.trim() || 'Kleinflow construction');
  const embed = `<iframe src="${escapeAttribute(present)}" title="${title}" width="800" height="500" style="border:0" allow="fullscreen"></iframe>`;
  return { ok: true, present, embed };
}
