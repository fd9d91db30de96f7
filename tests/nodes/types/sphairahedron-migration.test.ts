/**
 * Version 2 of the sphairahedron node took the published type names: a version-1 document's
 * type id is renamed to the published type with exactly the same angles, and the version-1 types
 * with no published twin are still there, so every saved document opens as it was.
 */
import { describe, expect, it } from 'vitest';
import {
  SPHAIRAHEDRON_TYPES,
  sphairahedronTypeById,
} from '../../../nodes/geometry/space/sphairahedron-types.ts';
import { migrateNodeParams } from '../../../nodes/graph/migrate.ts';
import { registry } from '../../../nodes/types/index.ts';
import { RENAMED_IN_V2 } from '../../../nodes/types/sphairahedron.ts';

/** The version-1 table's angles (as released), for the ids that were renamed. */
const V1_ANGLES: Record<string, object> = {
  'cube-333-a': {
    prism: [3, 3, 3],
    spherePlane: [
      [3, 3],
      [3, 3],
      [3, 3],
    ],
    sphereSphere: [3, 3, 3],
  },
  'cube-244-a': {
    prism: [2, 4, 4],
    spherePlane: [
      [4, 4],
      [2, 4],
      [2, 4],
    ],
    sphereSphere: [4, 4, 2],
  },
  'prism-333-a': { prism: [3, 3, 3], central: [3, 3, 3], corner: [3, 3], sphereSphere: 3 },
  'prism-333-b': { prism: [3, 3, 3], central: [2, 6, 6], corner: [3, 3], sphereSphere: 2 },
  'prism-244-a': { prism: [2, 4, 4], central: [2, 4, 4], corner: [4, 4], sphereSphere: 2 },
};
const V1_KEPT = ['cube-236-a', 'cube-333-b', 'cube-333-c', 'cube-333-d', 'cube-236-b'];

const def = registry.get('sphairahedron')!;

describe('sphairahedron node migration 1 → 2', () => {
  it.each(Object.entries(RENAMED_IN_V2))('%s becomes %s, a type with the same angles', (from, to) => {
    const t = sphairahedronTypeById(to)!;
    expect(t).toBeDefined();
    const {
      id: _id,
      label: _label,
      example: _example,
      kind: _kind,
      ...angles
    } = t as unknown as Record<string, unknown>;
    expect(angles).toEqual(V1_ANGLES[from]);
    const migrated = migrateNodeParams(def, { shape: from, zb: 0.25 }, 1);
    expect(migrated).toEqual({ ok: true, params: { shape: to, zb: 0.25 } });
  });

  it('keeps every other version-1 id, which still names a type', () => {
    for (const id of V1_KEPT) {
      expect(sphairahedronTypeById(id)).toBeDefined();
      expect(migrateNodeParams(def, { shape: id }, 1)).toEqual({ ok: true, params: { shape: id } });
    }
    expect(Object.keys(V1_ANGLES).every((id) => !SPHAIRAHEDRON_TYPES.some((t) => t.id === id))).toBe(true);
  });

  it('leaves a version-1 node without a shape on the default, the same angles as before', () => {
    expect(migrateNodeParams(def, {}, 1)).toEqual({ ok: true, params: {} });
  });
});
