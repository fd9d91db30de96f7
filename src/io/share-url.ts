/**
 * Share links: the whole graph travels in the URL fragment as `#g=` + base64url(raw DEFLATE(JSON)),
 * so nothing is uploaded anywhere. Decoding is bounded: a fragment longer than
 * LIMITS.shareFragmentMaxChars is refused before any work, and inflation streams in small pieces
 * and stops as soon as the output passes LIMITS.shareInflatedMaxBytes (a zip bomb costs
 * milliseconds, never memory).
 */
import { deflateSync, Inflate, strToU8 } from 'fflate';
import type { NodeRegistry } from '../../nodes/core/registry.ts';
import { LIMITS } from '../../nodes/core/scene.ts';
import type { GraphDoc } from '../../nodes/graph/document.ts';
import { loadDocument } from '../../nodes/graph/load.ts';
import { registry as appRegistry } from '../../nodes/types/index.ts';
import { decodeBase64Url, encodeBase64Url } from './base64url.ts';
import { compactDocumentJson } from './json-text.ts';

/** The fragment key: `#g=<payload>`. */
export const SHARE_KEY = 'g';

export type ShareEncodeResult = { ok: true; fragment: string } | { ok: false; message: string };
export type ShareDecodeResult = { ok: true; doc: GraphDoc } | { ok: false; message: string };

/**
 * `#g=…` for the document, or a message when the link would be longer than the cap (then the
 * user should save the file instead).
 */
export function encodeShareFragment(doc: GraphDoc): ShareEncodeResult {
  const json = compactDocumentJson(doc);
  const payload = encodeBase64Url(deflateSync(strToU8(json), { level: 9 }));
  if (payload.length > LIMITS.shareFragmentMaxChars) {
    return {
      ok: false,
      message: `this graph is too large for a share link (${payload.length} characters; the limit is ${LIMITS.shareFragmentMaxChars}): save it as a file instead`,
    };
  }
  return { ok: true, fragment: `#${SHARE_KEY}=${payload}` };
}

/** The `g` payload of a fragment, a whole URL, or `g=…`; null when there is none. */
export function sharePayload(text: string): string | null {
  const hash = text.includes('#') ? text.slice(text.indexOf('#') + 1) : text;
  for (const part of hash.split('&')) {
    if (part.startsWith(`${SHARE_KEY}=`)) return part.slice(SHARE_KEY.length + 1);
  }
  return null;
}

/** Compressed input is fed this many bytes at a time (DEFLATE expands a byte to at most ~1 KB). */
const INFLATE_PIECE = 1024;

type InflateResult =
  | { ok: true; bytes: Uint8Array }
  /** `inflated`: bytes produced before stopping (at most maxBytes plus one piece's output). */
  | { ok: false; message: string; inflated: number };

/** Raw-DEFLATE inflation that stops once the output exceeds `maxBytes`. */
export function boundedInflate(data: Uint8Array, maxBytes: number): InflateResult {
  const parts: Uint8Array[] = [];
  let total = 0;
  let finished = false;
  const stream = new Inflate((chunk, final) => {
    total += chunk.length;
    if (total <= maxBytes) parts.push(chunk);
    if (final) finished = true;
  });
  try {
    for (let o = 0; o < data.length && total <= maxBytes; o += INFLATE_PIECE) {
      const end = Math.min(data.length, o + INFLATE_PIECE);
      stream.push(data.subarray(o, end), end === data.length);
    }
  } catch (e) {
    const detail = (e as Error).message ?? String(e);
    return {
      ok: false,
      message: `the link's data is damaged (${detail}); was it cut off when copied?`,
      inflated: total,
    };
  }
  if (total > maxBytes) {
    return {
      ok: false,
      message: `the link's graph unpacks to more than ${maxBytes} bytes, larger than any graph Kleinflow opens from a link`,
      inflated: total,
    };
  }
  if (!finished) {
    return {
      ok: false,
      message: 'the link is incomplete (its data ends early); was it cut off when copied?',
      inflated: total,
    };
  }
  const out = new Uint8Array(total);
  let p = 0;
  for (const part of parts) {
    out.set(part, p);
    p += part.length;
  }
  return { ok: true, bytes: out };
}

/** Reads a graph from `#g=…` (or a whole URL with that fragment). Every failure is a message. */
export function decodeShareFragment(
  fragment: string,
  registry: NodeRegistry = appRegistry,
): ShareDecodeResult {
  const payload = sharePayload(fragment.trim());
  if (payload === null)
    return { ok: false, message: 'this is not a Kleinflow share link (it has no "#g=" part)' };
  if (payload.length === 0) return { ok: false, message: 'the share link is empty (nothing after "#g=")' };
  if (payload.length > LIMITS.shareFragmentMaxChars) {
    return {
      ok: false,
      message: `the share link is too long (${payload.length} characters; the limit is ${LIMITS.shareFragmentMaxChars})`,
    };
  }
  const decoded = decodeBase64Url(payload);
  if (!decoded.ok) return { ok: false, message: `the share link is damaged: ${decoded.message}` };
  const inflated = boundedInflate(decoded.bytes, LIMITS.shareInflatedMaxBytes);
  if (!inflated.ok) return { ok: false, message: inflated.message };
  let value: unknown;
  try {
    value = JSON.parse(new TextDecoder('utf-8', { fatal: true }).decode(inflated.bytes));
  } catch (e) {
    return { ok: false, message: `the share link does not hold a graph (${(e as Error).message})` };
  }
  const loaded = loadDocument(value, registry);
  if (!loaded.ok) {
    const shown = loaded.diagnostics.slice(0, 3).map((d) => d.message);
    const more = loaded.diagnostics.length > 3 ? ` (and ${loaded.diagnostics.length - 3} more)` : '';
    return { ok: false, message: `the share link's graph cannot be opened: ${shown.join('; ')}${more}` };
  }
  return { ok: true, doc: loaded.doc };
}
