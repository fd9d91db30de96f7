import { describe, expect, it } from 'vitest';
import { parseDocumentText } from '../../../../nodes/graph/load.ts';
import { registry } from '../../../../nodes/types/index.ts';
import { main } from '../../../../src/cli/main.ts';
import { serializeDocument } from '../../../../src/io/document-io.ts';
import { encodePng } from '../../../../src/io/png.ts';
import { embedGraph } from '../../../../src/io/png-graph.ts';
import { memoryIo } from '../../../support/memory-io.ts';
import { fedge, fnode, fpoint, graph, lineMirror } from '../../io/flower/support/flower-fixture.ts';

const flower = JSON.stringify(
  graph(lineMirror('m', [0, 0], [1, 0], false), {
    nodes: [fnode('Vec3', 'v'), fpoint('q', 2, 2)],
    edges: [fedge('Point', 'q', 'nowhere', 0)],
  }),
);

describe('kleinflow convert', () => {
  it('writes a Flower graph as a Kleinflow document and lists the notes on stderr', async () => {
    const { io, out, text } = memoryIo({ 'in.json': flower });
    expect(await main(['convert', 'in.json', '-o', 'out.kleinflow.json'], io)).toBe(0);
    const loaded = parseDocumentText(text('out.kleinflow.json'), registry);
    expect(loaded.ok).toBe(true);
    if (!loaded.ok) return;
    expect(loaded.doc.nodes.map((n) => n.type).sort()).toEqual([
      'line',
      'point',
      'point',
      'point',
      'reflection',
      'render',
      'tile',
    ]);
    expect(text('out.kleinflow.json')).toBe(serializeDocument(loaded.doc));
    expect(out.stderr).toMatch(/edges\[3\]: edge names socket "nowhere-in0"/);
    expect(out.stderr).toMatch(/in\.json: warning KF502 nodes\[4\]: Vec3 "v" cannot be mapped/);
    expect(out.stderr).toMatch(
      /in\.json: Flower graph → out\.kleinflow\.json: 7 nodes, 5 edges, 2 notes above\n$/,
    );
    expect(out.stdout).toBe('');
  });

  it('writes to stdout without -o, and converts a Kleinflow PNG back to its document', async () => {
    const first = memoryIo({ 'in.json': flower });
    await main(['convert', 'in.json'], first.io);
    const doc = parseDocumentText(first.out.stdout, registry);
    if (!doc.ok) throw new Error('stdout is not a document');
    const png = embedGraph({ width: 1, height: 1, data: new Uint8Array(4) }, doc.doc);
    const second = memoryIo({ 'pic.png': png });
    expect(await main(['convert', 'pic.png'], second.io)).toBe(0);
    expect(second.out.stdout).toBe(first.out.stdout);
    expect(second.out.stderr).toMatch(/Kleinflow PNG → stdout/);
  });

  it('fails with exit 1 and the reasons when the input cannot be opened', async () => {
    const { io, out } = memoryIo({
      'bad.json': '{"nodes": 3',
      'plain.png': encodePng({ width: 1, height: 1, data: new Uint8Array(4) }),
    });
    expect(await main(['convert', 'bad.json', '-o', 'x.json'], io)).toBe(1);
    expect(out.stderr).toMatch(/bad\.json: error KF101 \(document\): not valid JSON/);
    expect(await main(['convert', 'plain.png'], io)).toBe(1);
    expect(out.stderr).toMatch(/this PNG has no Kleinflow graph inside/);
    expect(await main(['convert', 'missing.json'], io)).toBe(1);
    expect(out.stderr).toMatch(/cannot read "missing\.json": no such file/);
  });

  it('refuses to overwrite its input and needs an input (usage errors, exit 2)', async () => {
    const { io, out } = memoryIo({ 'in.json': flower });
    expect(await main(['convert', 'in.json', '-o', 'in.json'], io)).toBe(2);
    expect(out.stderr).toMatch(/would overwrite the input/);
    expect(await main(['convert'], io)).toBe(2);
    expect(out.stderr).toMatch(/missing INPUT/);
  });
});
