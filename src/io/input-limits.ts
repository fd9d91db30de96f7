/**
 * How much Kleinflow reads from any one input before it refuses it, for every front end (CLI
 * files, files opened or dropped in the editor, pasted text). Reading stops at the limit, so an
 * endless input (`/dev/zero`, a runaway pipe) costs at most the limit, never all memory. The
 * README's "Limits" section and the CLI's --help quote these numbers.
 */

import { isPng } from './png.ts';

const MiB = 1024 * 1024;

export const INPUT_LIMITS = {
  /**
   * A graph as JSON text (a file, pasted text, the graph inside a PNG). A 5,000-node document is
   * about 2 MB; pictures travel inline (at most 8 MB of data URL each), so 64 MB leaves room.
   */
  documentBytes: 64 * MiB,
  /** A PNG file (its pixels are skipped; only its text chunks are read). A 16384² export is far below. */
  pngBytes: 512 * MiB,
  /**
   * The chunks of one PNG. Reading skips through them without copying, but each is a step: a
   * 512 MB PNG in libpng's usual 8 KB IDAT chunks has 65,536, so this leaves room and stops a file
   * of millions of empty chunks at once. (Text keywords are at most 79 bytes, the PNG limit, and the
   * graph inside a PNG is held to documentBytes before its text is decoded.)
   */
  pngChunks: 100_000,
  /**
   * One entry of a points file, whitespace around it included. Points files are streamed, so
   * their total size is unlimited; this bound keeps memory small whatever the file holds.
   */
  pointEntryChars: 4096,
} as const;

/** "64 MB", "512 MB", "4 KB": binary units written the way people read them. */
export function formatBytes(n: number): string {
  if (n >= MiB) return `${+(n / MiB).toFixed(1)} MB`;
  if (n >= 1024) return `${+(n / 1024).toFixed(1)} KB`;
  return `${n} bytes`;
}

/** The most bytes a file starting with `head` (at least 8 bytes of it) may have, and its name in messages. */
export function fileLimit(head: Uint8Array): { bytes: number; what: string } {
  return isPng(head)
    ? { bytes: INPUT_LIMITS.pngBytes, what: 'a PNG file' }
    : { bytes: INPUT_LIMITS.documentBytes, what: 'a graph file' };
}

/** One line for an input past its limit: `it is larger than 64 MB, the limit for a graph file`. */
export const tooLargeMessage = (limit: { bytes: number; what: string }, size?: number): string =>
  `it is ${size === undefined ? 'larger than' : `${formatBytes(size)}, more than`} ${formatBytes(limit.bytes)}, the limit for ${limit.what}`;
