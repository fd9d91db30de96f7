/**
 * What the CLI embeds in its exports is the loaded document: an older document is embedded
 * migrated (so the PNG reopens at the current version), never as the text it was read from.
 */
import { describe, expect, it } from 'vitest';
import type { CliIo, CliOutput } from '../../../src/cli/command.ts';
import { loadGraph } from '../../../src/cli/load-graph.ts';
import { CURRENT_RING, ringRegistry, v1RingDoc } from '../../support/versioned-node.ts';

const silent: CliOutput = { write: () => {} };

/** An in-memory CliIo holding one file. */
function ioWith(path: string, text: string): CliIo {
  const bytes = new TextEncoder().encode(text);
  return {
    stdout: silent,
    stderr: silent,
    open: async (p) => {
      if (p !== path) throw Object.assign(new Error('missing'), { code: 'ENOENT' });
      return {
        size: bytes.length,
        chunks: (async function* () {
          yield bytes;
        })(),
      };
    },
    writeFile: async () => {},
  };
}

describe('loadGraph', () => {
  it('hands exports the migrated document, not the older text it read', async () => {
    const old = JSON.stringify(v1RingDoc());
    const loaded = await loadGraph(ioWith('old.json', old), 'old.json', ringRegistry);
    expect(loaded.doc).toBeDefined();
    const embedded = JSON.parse(loaded.text) as { nodes: { id: string }[] };
    expect(embedded.nodes.find((n) => n.id === 'ring')).toMatchObject(CURRENT_RING);
    expect(loaded.text).not.toBe(old);
  });

  it('is deterministic: the same file gives the same embedded text', async () => {
    const text = JSON.stringify(v1RingDoc());
    const a = await loadGraph(ioWith('a.json', text), 'a.json', ringRegistry);
    const b = await loadGraph(ioWith('a.json', text), 'a.json', ringRegistry);
    expect(a.text).toBe(b.text);
  });
});
