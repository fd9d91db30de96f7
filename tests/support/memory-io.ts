/**
 * A CliIo over an in-memory file table for running `kleinflow` commands in process: what they write
 * to stdout/stderr is captured, files they write land in the table (read back with `text`).
 */
import type { CliIo } from '../../src/cli/command.ts';

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
    readFile: async (path) => {
      const data = table.get(path);
      if (!data) throw Object.assign(new Error('missing'), { code: 'ENOENT' });
      return data;
    },
    writeFile: async (path, data) =>
      void table.set(path, typeof data === 'string' ? new TextEncoder().encode(data) : data),
  };
  const text = (path: string) => new TextDecoder().decode(table.get(path));
  return { io, out, text };
}
