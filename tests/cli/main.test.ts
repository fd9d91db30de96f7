import { describe, expect, it } from 'vitest';
import type { CliIo } from '../../src/cli/command.ts';
import { main } from '../../src/cli/main.ts';

const GRAPH = JSON.stringify({
  format: 'kleinflow',
  version: 1,
  meta: {},
  nodes: [{ id: 'x', type: 'foo', position: [0, 0], params: {} }],
  edges: [],
  view: { center: [0, 0], scale: 4 },
});

function memoryIo(files: Record<string, string>, stdoutWrite?: (t: string) => void) {
  const out: string[] = [];
  const err: string[] = [];
  const io: CliIo = {
    stdout: { write: stdoutWrite ?? ((t) => void out.push(t)) },
    stderr: { write: (t) => void err.push(t) },
    readFile: async (path) => {
      if (!(path in files)) throw Object.assign(new Error('nope'), { code: 'ENOENT' });
      return new TextEncoder().encode(files[path]);
    },
    writeFile: async () => {},
  };
  return { io, out, err };
}

describe('main (in process)', () => {
  it('runs a command through the io it is given', async () => {
    const { io, out } = memoryIo({ 'g.json': GRAPH });
    expect(await main(['check', 'g.json'], io)).toBe(1);
    expect(out.join('')).toMatch(/^error KF203 nodes\[0\]\.type \(node "x"\)/);
  });

  it('turns an unexpected exception into one "internal error" line and exit 70', async () => {
    const { io, err } = memoryIo({ 'g.json': GRAPH }, () => {
      throw new Error('disk on fire');
    });
    expect(await main(['check', 'g.json'], io)).toBe(70);
    expect(err.join('')).toBe('kleinflow: internal error: disk on fire\n');
  });
});
