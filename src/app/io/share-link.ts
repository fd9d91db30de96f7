/**
 * Share links in the page: the link for the current document (this page's address + `#g=…`), and
 * the graph a page was opened with. Encoding and decoding are src/io/share-url.ts.
 */
import type { GraphDoc } from '../../../nodes/graph/document.ts';
import { decodeShareFragment, encodeShareFragment, sharePayload } from '../../io/share-url.ts';

export type ShareLinkResult = { ok: true; url: string } | { ok: false; message: string };

/** The page address without query mode or fragment, plus the document's `#g=…`. */
export function shareLinkFor(doc: GraphDoc, where: Pick<Location, 'origin' | 'pathname'>): ShareLinkResult {
  const encoded = encodeShareFragment(doc);
  return encoded.ok ? { ok: true, url: `${where.origin}${where.pathname}${encoded.fragment}` } : encoded;
}

export type StartupLink =
  | { kind: 'none' }
  | { kind: 'ok'; doc: GraphDoc }
  | { kind: 'broken'; message: string };

/** What the page's `#g=…` fragment holds (none when the fragment has no `g=` part). */
export function readStartupLink(hash: string): StartupLink {
  if (!hash.startsWith('#') || sharePayload(hash) === null) return { kind: 'none' };
  const decoded = decodeShareFragment(hash);
  return decoded.ok ? { kind: 'ok', doc: decoded.doc } : { kind: 'broken', message: decoded.message };
}

/** Removes the fragment from the address bar without reloading, so a reload does not apply it again. */
export function clearFragment(): void {
  const { pathname, search } = window.location;
  window.history.replaceState(window.history.state, '', `${pathname}${search}`);
}
