/** The real process's CliIo: files through node:fs, output through process.stdout/stderr. */
import { once } from 'node:events';
import { open, writeFile } from 'node:fs/promises';
import type { CliIo, CliOutput, InputFile } from './command.ts';

/** Bytes per read: large enough that a 10 GB points file is a few thousand reads per second. */
const READ_PIECE = 1 << 20;

function output(stream: NodeJS.WriteStream): CliOutput {
  return {
    write: (t) => void stream.write(t),
    isTTY: stream.isTTY === true,
    drain: async () => {
      if (stream.writableNeedDrain) await once(stream, 'drain');
    },
  };
}

async function openFile(path: string): Promise<InputFile> {
  // "-" is standard input (a pipe, socket or terminal: /dev/stdin cannot open a socket).
  if (path === '-') return { size: null, chunks: process.stdin };
  const handle = await open(path, 'r');
  let size: number | null;
  try {
    const stat = await handle.stat();
    if (stat.isDirectory()) throw Object.assign(new Error(`EISDIR: "${path}"`), { code: 'EISDIR' });
    size = stat.isFile() ? stat.size : null;
  } catch (e) {
    await handle.close();
    throw e;
  }
  async function* chunks(): AsyncGenerator<Uint8Array> {
    try {
      for (;;) {
        // A fresh buffer per piece: callers may keep the pieces they were given.
        const { bytesRead, buffer } = await handle.read(new Uint8Array(READ_PIECE), 0, READ_PIECE, null);
        if (bytesRead === 0) return;
        yield buffer.subarray(0, bytesRead);
      }
    } finally {
      await handle.close();
    }
  }
  return { size, chunks: chunks() };
}

export function nodeIo(): CliIo {
  return {
    stdout: output(process.stdout),
    stderr: output(process.stderr),
    open: openFile,
    writeFile: (path, data) => writeFile(path, data),
  };
}
