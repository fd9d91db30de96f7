import { describe, expect, it } from 'vitest';
import { main } from '../../src/cli/main.ts';
import { memoryIo } from '../support/memory-io.ts';

const GRAPH = JSON.stringify({
  format: 'kleinflow',
  version: 1,
  meta: {},
  nodes: [{ id: 'x', type: 'foo', position: [0, 0], params: {} }],
  edges: [],
  view: { center: [0, 0], scale: 4 },
});

describe('main (in process)', () => {
  it('runs a command through the io it is given', async () => {
    const { io, out } = memoryIo({ 'g.json': GRAPH });
    expect(await main(['check', 'g.json'], io)).toBe(1);
    expect(out.stdout).toMatch(/^error KF203 nodes\[0\]\.type \(node "x"\)/);
  });

  it('turns an unexpected exception into one "internal error" line and exit 70', async () => {
    const { io, out } = memoryIo(
      { 'g.json': GRAPH },
      {
        stdoutWrite: () => {
          throw new Error('disk on fire');
        },
      },
    );
    expect(await main(['check', 'g.json'], io)).toBe(70);
    expect(out.stderr).toBe('kleinflow: internal error: disk on fire\n');
  });
});
