/** The real process's CliIo: files through node:fs, output through process.stdout/stderr. */
import { readFile, writeFile } from 'node:fs/promises';
import type { CliIo } from './command.ts';

export function nodeIo(): CliIo {
  return {
    stdout: { write: (t) => void process.stdout.write(t), isTTY: process.stdout.isTTY === true },
    stderr: { write: (t) => void process.stderr.write(t), isTTY: process.stderr.isTTY === true },
    readFile: async (path) => new Uint8Array(await readFile(path)),
    writeFile: (path, data) => writeFile(path, data),
  };
}
