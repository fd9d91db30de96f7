import { describe, expect, it } from 'vitest';
import type { Diagnostic } from '../../../nodes/core/diagnostics.ts';
import { LIMITS } from '../../../nodes/core/scene.ts';
import { DOC_VERSION, emptyDocument } from '../../../nodes/graph/document.ts';
import { loadDocument, parseDocumentText } from '../../../nodes/graph/load.ts';
import { type DocMigration, migrateDocument, type RawDoc } from '../../../nodes/graph/migrate.ts';
import { registry } from '../../../nodes/types/index.ts';
import { doc, edge, node } from '../support/doc.ts';

const valid = () =>
  doc(
    [node('p1', 'point', { x: 0.5, y: 0.25 }), node('c1', 'circle', { radius: 1 }), node('out', 'render')],
    [edge('e1', 'p1.point', 'c1.center')],
  );

function failure(r: ReturnType<typeof loadDocument>): Diagnostic[] {
  expect(r.ok).toBe(false);
  return r.diagnostics;
}

describe('parseDocumentText / loadDocument', () => {
  it('loads a valid document unchanged (JSON round trip)', () => {
    const d = valid();
    const r = parseDocumentText(JSON.stringify(d), registry);
    if (!r.ok) throw new Error(JSON.stringify(r.diagnostics));
    expect(r.doc).toEqual(d);
    expect(r.migratedFrom).toBe(DOC_VERSION);
    expect(r.diagnostics).toEqual([]);
    const empty = loadDocument(emptyDocument('x'), registry);
    expect(empty.ok).toBe(true);
  });

  it('keeps extra meta fields (meta is open) and labels', () => {
    const d = { ...valid(), meta: { title: 't', author: 'A. Möbius' } };
    d.nodes[0] = { ...d.nodes[0], label: 'A', version: 1 };
    const r = loadDocument(JSON.parse(JSON.stringify(d)), registry);
    if (!r.ok) throw new Error(JSON.stringify(r.diagnostics));
    expect(r.doc.meta.author).toBe('A. Möbius');
    expect(r.doc.nodes[0].label).toBe('A');
  });

  it('KF101: text that is not JSON', () => {
    const [d] = failure(parseDocumentText('{"format": "kleinflow", ', registry));
    expect(d).toMatchObject({ code: 'KF101', path: '(document)', severity: 'error' });
    expect(d.message).toMatch(/^not valid JSON: /);
    expect(failure(parseDocumentText('', registry))[0].code).toBe('KF101');
  });

  it('KF102: JSON that is not an object', () => {
    for (const text of ['[1, 2]', 'null', '42', '"kleinflow"']) {
      const [d] = failure(parseDocumentText(text, registry));
      expect(d).toMatchObject({ code: 'KF102', path: '(document)' });
    }
    expect(failure(parseDocumentText('[]', registry))[0].message).toContain('an array');
  });

  it('KF103: another format, or none', () => {
    const [d] = failure(loadDocument({ ...valid(), format: 'flower' }, registry));
    expect(d).toMatchObject({ code: 'KF103', path: 'format' });
    expect(d.message).toContain('"flower"');
    const { format: _f, ...rest } = valid();
    expect(failure(loadDocument(rest, registry))[0]).toMatchObject({ code: 'KF103', path: 'format' });
  });

  it('rejects ∞ written as 1e999 and NaN, naming the path', () => {
    const text = JSON.stringify(valid()).replace('"scale":4', '"scale":1e999');
    expect(text).toContain('1e999');
    const [d] = failure(parseDocumentText(text, registry));
    expect(d).toMatchObject({ code: 'KF102', path: 'view.scale' });
    expect(d.message.startsWith('view.scale: ')).toBe(true);

    const pos = JSON.stringify(valid()).replace('"position":[0,0]', '"position":[-1e999,0]');
    expect(failure(parseDocumentText(pos, registry))[0].path).toBe('nodes[0].position[0]');

    const nan = valid();
    nan.view = { center: [0, Number.NaN], scale: 4 };
    expect(failure(loadDocument(nan, registry))[0].path).toBe('view.center[1]');
  });

  it('KF102: every schema problem comes back with its path', () => {
    const d = valid() as unknown as {
      nodes: Record<string, unknown>[];
      edges: Record<string, unknown>[];
      view: Record<string, unknown>;
    };
    d.nodes.push(node('n3', 'circle'), node('n4', 'circle'));
    d.nodes[3].id = '';
    d.nodes[4].params = [1, 2];
    d.nodes[1].position = [0];
    d.edges[0].to = { node: 'c1' };
    d.view.scale = -1;
    const ds = failure(loadDocument(d, registry));
    for (const x of ds) expect(x.code).toBe('KF102');
    const paths = ds.map((x) => x.path);
    expect(paths).toEqual(
      expect.arrayContaining([
        'nodes[3].id',
        'nodes[4].params',
        'nodes[1].position',
        'edges[0].to.port',
        'view.scale',
      ]),
    );
    const scale = ds.find((x) => x.path === 'view.scale')!;
    expect(scale.message).toBe('view.scale: expected a positive number');
  });

  it('KF102: unknown keys are rejected (strict objects) at their object path', () => {
    const d = valid() as unknown as { nodes: Record<string, unknown>[] };
    d.nodes[2].colour = 'red';
    const [x] = failure(loadDocument(d, registry));
    expect(x.path).toBe('nodes[2]');
    expect(x.message).toContain('colour');
  });

  it('lists at most 50 schema problems and says how many more there are', () => {
    const d = valid() as unknown as { nodes: unknown[] };
    d.nodes = Array.from({ length: 80 }, () => ({ id: '', type: 'point', position: [0, 0], params: {} }));
    const ds = failure(loadDocument(d, registry));
    expect(ds).toHaveLength(51);
    expect(ds[50].message).toBe('…and 30 more problems');
  });

  it('KF104: a document from a newer Kleinflow is rejected', () => {
    const [d] = failure(loadDocument({ ...valid(), version: DOC_VERSION + 1 }, registry));
    expect(d).toMatchObject({ code: 'KF104', path: 'version' });
    expect(d.message).toContain(`${DOC_VERSION + 1}`);
  });

  it('KF102: a version that is not a positive integer', () => {
    for (const version of [0, -1, 1.5, '1', null]) {
      const [d] = failure(loadDocument({ ...valid(), version }, registry));
      expect(d).toMatchObject({ code: 'KF102', path: 'version' });
    }
  });

  it('KF105: too many nodes', () => {
    const d = valid() as unknown as { nodes: unknown[] };
    const n = LIMITS.maxNodes + 1;
    d.nodes = Array.from({ length: n }, (_, i) => node(`n${i}`, 'point'));
    const [x] = failure(loadDocument(d, registry));
    expect(x).toMatchObject({ code: 'KF105', path: 'nodes' });
    expect(x.message).toContain(String(n));
    d.nodes.pop();
    expect(loadDocument(d, registry).ok).toBe(true);
  });
});

describe('document migrations', () => {
  // A fake format history: v1 → v2 renames meta.name to meta.title; v2 → v3 moves view.zoom to view.scale.
  const table: Record<number, DocMigration> = {
    1: (d) => {
      const { name, ...meta } = (d.meta ?? {}) as Record<string, unknown>;
      return { ...d, meta: { ...meta, title: name } };
    },
    2: (d) => {
      const { zoom, ...view } = d.view as Record<string, unknown>;
      return { ...d, view: { ...view, scale: zoom } };
    },
  };
  const v1 = (): RawDoc => ({
    format: 'kleinflow',
    version: 1,
    meta: { name: 'old' },
    nodes: [],
    edges: [],
    view: { center: [0, 0], zoom: 3 },
  });

  it('runs every step from the document version up to the target', () => {
    const input = v1();
    const r = migrateDocument(input, table, 3);
    if (!r.ok) throw new Error(r.message);
    expect(r.from).toBe(1);
    expect(r.doc).toEqual({
      format: 'kleinflow',
      version: 3,
      meta: { title: 'old' },
      nodes: [],
      edges: [],
      view: { center: [0, 0], scale: 3 },
    });
    expect(input).toEqual(v1()); // the input is not modified
  });

  it('starts at the document version (a v2 document skips step 1)', () => {
    const d = { ...v1(), version: 2, meta: { title: 'new' } };
    const r = migrateDocument(d, table, 3);
    if (!r.ok) throw new Error(r.message);
    expect(r.from).toBe(2);
    expect(r.doc.meta).toEqual({ title: 'new' });
    expect(r.doc.view).toEqual({ center: [0, 0], scale: 3 });
  });

  it('leaves a current document alone and rejects newer ones', () => {
    const d = { ...v1(), version: 3 };
    const r = migrateDocument(d, table, 3);
    expect(r).toEqual({ ok: true, doc: d, from: 3 });
    const newer = migrateDocument({ ...v1(), version: 4 }, table, 3);
    expect(newer.ok).toBe(false);
    if (!newer.ok) expect(newer.message).toContain('newer');
  });

  it('fails clearly on a missing step', () => {
    const r = migrateDocument(v1(), { 1: table[1] }, 3);
    expect(r).toEqual({ ok: false, message: 'version: no migration from version 2 to 3' });
  });

  it('loadDocument migrates, then validates the migrated document', () => {
    const r = loadDocument(v1(), registry, { migrations: table, target: 3 });
    if (!r.ok) throw new Error(JSON.stringify(r.diagnostics));
    expect(r.migratedFrom).toBe(1);
    expect(r.doc.version).toBe(3);
    expect(r.doc.view.scale).toBe(3);
    // a step that produces an invalid document is caught by validation, with the path
    const bad = loadDocument({ ...v1(), view: { center: [0, 0], zoom: -2 } }, registry, {
      migrations: table,
      target: 3,
    });
    expect(failure(bad)[0]).toMatchObject({ code: 'KF102', path: 'view.scale' });
    // future documents against the fake target
    expect(
      failure(loadDocument({ ...v1(), version: 4 }, registry, { migrations: table, target: 3 }))[0].code,
    ).toBe('KF104');
  });

  it('a migration that throws becomes a diagnostic, not an exception', () => {
    const throwing = {
      1: () => {
        throw new Error('boom');
      },
      2: table[2],
    };
    const [d] = failure(loadDocument(v1(), registry, { migrations: throwing, target: 3 }));
    expect(d).toMatchObject({ code: 'KF102', path: 'version' });
    expect(d.message).toContain('boom');
  });
});
