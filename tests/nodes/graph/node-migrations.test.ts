import { describe, expect, it } from 'vitest';
import { defineNode } from '../../../nodes/core/define-node.ts';
import { createRegistry } from '../../../nodes/core/registry.ts';
import { evaluateGraph } from '../../../nodes/graph/evaluate.ts';
import { migrateNodeParams } from '../../../nodes/graph/migrate.ts';
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

describe('evaluation migrates old nodes', () => {
  it('an old node evaluates with its migrated params', () => {
    const ev = evaluateGraph(doc([{ ...node('d', 'test-disk', { rad: 2.5 }), version: 1 }]), registry);
    expect(ev.nodes.get('d')?.outputs).toEqual({ radius: 2.5 });
    expect(ev.diagnostics.filter((d) => d.nodeId === 'd')).toEqual([]);
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
