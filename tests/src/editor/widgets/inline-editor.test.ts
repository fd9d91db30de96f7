/** Which unconnected inputs get an inline editor: the 3D value types too (point3, sphere, plane). */
import { describe, expect, it } from 'vitest';
import type { InputSpec } from '../../../../nodes/core/define-node.ts';
import { registry } from '../../../../nodes/types/index.ts';
import { hasInlineEditor } from '../../../../src/editor/widgets/inline-editor.ts';

describe('hasInlineEditor, 3D types', () => {
  it.each([
    ['point3', [1, 2, 3], true],
    ['point3', [1, 2], false],
    ['sphere', { center: [0, 0, 0], radius: 1 }, true],
    ['sphere', { center: [0, 0], radius: 1 }, false],
    ['plane', { point: [0, 0, 0], normal: [0, 0, 1] }, true],
    ['plane', { point: [0, 0, 0] }, false],
    ['element3', undefined, false],
    ['seed3', undefined, false],
  ] as const)('%s %j → %s', (type, value, want) => {
    expect(hasInlineEditor({ type } as InputSpec, value)).toBe(want);
  });

  it('every 3D node’s point, sphere and plane inputs are editable with their defaults', () => {
    for (const def of registry.all.filter((d) => d.category === '3D')) {
      for (const [name, spec] of Object.entries(def.inputs)) {
        if (['point3', 'sphere', 'plane'].includes(spec.type))
          expect(hasInlineEditor(spec, undefined), `${def.type}.${name}`).toBe(true);
      }
    }
  });
});
