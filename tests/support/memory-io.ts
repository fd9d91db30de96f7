/**
 * A CliIo over an in-memory file table for running `kleinflow` commands in process: what they write
 * to stdout/stderr is captured, files they write land in the table (read back with `text`).
 */
import type { CliIo } from '../../src/cli/command.ts';

/** Bytes per piece of a file read through `open`. */
const PIECE = 1000;

export function memoryIo(
  files: Record<string, Uint8Array | string>,
  options: { stdoutWrite?: (text: string) => void } = {},
) {
  const out = { stdout: '', stderr: '' };
  const table = new Map(
    Object.entries(files).map(([k, v]) => [k, typeof v === 'string' ? new TextEncoder().encode(v) : v]),
  );
  const io: CliIo = {
    stdout: {
      write:
        options.stdoutWrite ??
        ((t) => {
          out.stdout += t;
        }),
    },
    stderr: {
      write: (t) => {
        out.stderr += t;
      },
    },
    open: async (path) => {
      const data = table.get(path);
      if (!data) throw Object.assign(new Error('missing'), { code: 'ENOENT' });
      async function* chunks() {
        // Small pieces, so readers meet entries and characters split across pieces.
        for (let o = 0; o < data!.length; o += PIECE) yield data!.subarray(o, o + PIECE);
      }
      return { size: data.length, chunks: chunks() };
    },
    writeFile: async (path, data) =>
      void table.set(path, typeof data === 'string' ? new TextEncoder().encode(data) : data),
  };
  const text = (path: string) => new TextDecoder().decode(table.get(path));
  return { io, out, text };
}
