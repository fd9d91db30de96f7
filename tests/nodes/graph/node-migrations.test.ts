import { describe, expect, it } from 'vitest';
import { defineNode } from '../../../nodes/core/define-node.ts';
import { createRegistry } from '../../../nodes/core/registry.ts';
import { evaluateGraph } from '../../../nodes/graph/evaluate.ts';
import { loadDocument } from '../../../nodes/graph/load.ts';
import { migrateNodeParams, migrateNodes, nodeVersionProblem } from '../../../nodes/graph/migrate.ts';
import { doc, node } from '../support/doc.ts';

/**
 * A fake node type at version 3: v1 stored the radius as "rad", v2 stored the diameter "size",
 * v3 stores "radius".
 */
const disk = defineNode({
  type: 'test-disk',
  version: 3,
  label: 'Disk',
  category: 'Geometry',
  color: '#000000',
  doc: 'a disk of a given radius',
  inputs: { radius: { type: 'number', label: 'radius', default: 1, min: 0 } },
  outputs: { radius: { type: 'number' } },
  params: {},
  migrations: {
    1: ({ rad, ...rest }) => ({ ...rest, size: 2 * (rad as number) }),
    2: ({ size, ...rest }) => ({ ...rest, radius: (size as number) / 2 }),
  },
  evaluate: ({ inputs }) => ({ outputs: { radius: inputs.radius } }),
});
const registry = createRegistry([disk]);

describe('migrateNodeParams', () => {
  it("runs the type's migrations from the node's version up to the type's", () => {
    expect(migrateNodeParams(disk, { rad: 3 }, 1)).toEqual({ ok: true, params: { radius: 3 } });
    expect(migrateNodeParams(disk, { size: 3 }, 2)).toEqual({ ok: true, params: { radius: 1.5 } });
    expect(migrateNodeParams(disk, { radius: 4 }, 3)).toEqual({ ok: true, params: { radius: 4 } });
    expect(migrateNodeParams(disk, { rad: 2 })).toEqual({ ok: true, params: { radius: 2 } }); // no version = 1
  });

  it("does not modify the document's params", () => {
    const params = { rad: 3 };
    migrateNodeParams(disk, params, 1);
    expect(params).toEqual({ rad: 3 });
  });

  it('rejects newer versions, missing steps and throwing steps', () => {
    expect(migrateNodeParams(disk, {}, 4)).toMatchObject({
      ok: false,
      message: expect.stringContaining('newer'),
    });
    const gap = { ...disk, migrations: { 2: disk.migrations![2] } };
    expect(migrateNodeParams(gap, {}, 1)).toMatchObject({
      ok: false,
      message: expect.stringContaining('from version 1 to 2'),
    });
    const throws = {
      ...disk,
      migrations: {
        ...disk.migrations,
        2: () => {
          throw new Error('bad size');
        },
      },
    };
    expect(migrateNodeParams(throws, { rad: 1 }, 1)).toMatchObject({
      ok: false,
      message: expect.stringContaining('bad size'),
    });
  });
});

describe('migrateNodes (run once, on load and paste)', () => {
  it('migrates the nodes inside a group (and groups inside groups) like the document’s', () => {
    const inner = { ...node('d', 'test-disk', { rad: 2 }), version: 1 };
    const body = { nodes: [inner], edges: [], inputs: [], outputs: [] };
    const group = {
      ...node('g', 'group'),
      group: { ...body, nodes: [{ ...node('h', 'group'), group: body }] },
    };
    const [out] = migrateNodes([group], registry);
    const migrated = out.group!.nodes[0].group!.nodes[0];
    expect(migrated).toEqual({ ...inner, version: 3, params: { radius: 2 } });
    const current = { ...node('g', 'group'), group: { ...body, nodes: [{ ...inner, version: 3 }] } };
    expect(migrateNodes([current], registry)[0]).toBe(current);
  });

  it('brings old nodes to their type version and leaves current nodes and placeholders as they are', () => {
    const current = { ...node('x', 'test-disk', { radius: 1 }), version: 3 };
    const placeholder = { ...node('u', 'no-such-type', { rad: 1 }), version: 1 };
    const [old, same, kept] = migrateNodes(
      [{ ...node('d', 'test-disk', { rad: 2.5 }), version: 1 }, current, placeholder],
      registry,
    );
    expect(old).toEqual({ ...node('d', 'test-disk', { radius: 2.5 }), version: 3 });
    expect(same).toBe(current);
    expect(kept).toBe(placeholder);
  });

  it('keeps a node whose migration fails exactly as it was, and evaluation says why', () => {
    const badStep = { ...disk, migrations: { ...disk.migrations, 2: () => 'not params' as never } };
    const withBadStep = createRegistry([badStep]);
    const original = { ...node('d', 'test-disk', { rad: 1 }), version: 1 };
    const [kept] = migrateNodes([original], withBadStep);
    expect(kept).toBe(original);
    const ev = evaluateGraph(doc([kept]), withBadStep);
    expect(ev.diagnostics).toContainEqual(
      expect.objectContaining({
        code: 'KF309',
        nodeId: 'd',
        message: expect.stringContaining('failed when it was loaded'),
      }),
    );
  });

  it('loading migrates: the loaded document is current and evaluates without migrating', () => {
    const loaded = loadDocument(doc([{ ...node('d', 'test-disk', { rad: 2.5 }), version: 1 }]), registry);
    if (!loaded.ok) throw new Error('did not load');
    expect(loaded.doc.nodes[0]).toMatchObject({ version: 3, params: { radius: 2.5 } });
    const ev = evaluateGraph(loaded.doc, registry);
    expect(ev.nodes.get('d')?.outputs).toEqual({ radius: 2.5 });
    expect(ev.diagnostics.filter((d) => d.nodeId === 'd')).toEqual([]);
  });
});

describe('evaluation never migrates', () => {
  it('an old node that did not go through loading is reported (KF309), not silently migrated', () => {
    const ev = evaluateGraph(doc([{ ...node('d', 'test-disk', { rad: 2.5 }), version: 1 }]), registry);
    expect(ev.nodes.get('d')?.outputs).toBeUndefined();
    expect(ev.diagnostics).toContainEqual(expect.objectContaining({ code: 'KF309', nodeId: 'd' }));
  });

  it('nodeVersionProblem names a newer version and a missing step', () => {
    expect(nodeVersionProblem(disk, 3)).toBeNull();
    expect(nodeVersionProblem(disk, 4)).toContain('newer');
    expect(nodeVersionProblem({ ...disk, migrations: { 2: disk.migrations![2] } }, 1)).toContain(
      'no migration from version 1 to 2',
    );
  });

  it('KF309: a node from a newer Kleinflow is reported at its version path', () => {
    const ev = evaluateGraph(
      doc([
        { ...node('x', 'test-disk'), version: 3 },
        { ...node('d', 'test-disk', { radius: 1 }), version: 9 },
      ]),
      registry,
    );
    expect(ev.diagnostics.filter((d) => d.code !== 'KF210')).toEqual([
      expect.objectContaining({ code: 'KF309', severity: 'error', nodeId: 'd', path: 'nodes[1].version' }),
    ]);
    expect(ev.nodes.get('d')?.outputs).toBeUndefined();
    expect(ev.nodes.get('x')?.outputs).toEqual({ radius: 1 });
  });
});
