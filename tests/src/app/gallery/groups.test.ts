/** The gallery's sections hold every example exactly once, and search finds what people type. */
import { describe, expect, it } from 'vitest';
import type { Example } from '../../../../src/app/examples.ts';
import { GALLERY_SECTIONS, galleryGroups, oneLine } from '../../../../src/app/gallery/groups.ts';
import { EXAMPLES_3D_DIR, exampleNames } from '../../../../src/cli/examples.ts';

const fake = (id: string, title: string, description = ''): Example =>
  ({ id, title, description, doc: {} }) as unknown as Example;

describe('gallery sections', () => {
  it('place every bundled example in exactly one section, and name no missing file', () => {
    const ids = GALLERY_SECTIONS.flatMap((s) => s.ids);
    expect(new Set(ids).size).toBe(ids.length);
    expect([...ids].sort()).toEqual([...exampleNames(), ...exampleNames(EXAMPLES_3D_DIR)].sort());
  });

  it('put an example no section names under "More" instead of hiding it', () => {
    const groups = galleryGroups([fake('kaleidoscope-333', '*333'), fake('brand-new', 'New one')]);
    expect(groups.map((g) => g.title)).toEqual(['Kaleidoscopes', 'More']);
    expect(groups[1].examples.map((e) => e.id)).toEqual(['brand-new']);
  });

  it('search matches every word in title or description, ignoring case and accents', () => {
    const examples = [
      fake('schottky-pair', 'Schottky group: two Möbius generators'),
      fake('loxodromic-spiral', 'Fig. 16 — loxodromic Möbius transformation', 'A spiral orbit.'),
      fake('kaleidoscope-333', '*333 kaleidoscope'),
    ];
    const ids = (q: string) => galleryGroups(examples, q).flatMap((g) => g.examples.map((e) => e.id));
    expect(ids('mobius')).toEqual(['schottky-pair', 'loxodromic-spiral']);
    expect(ids('MÖBIUS spiral')).toEqual(['loxodromic-spiral']);
    expect(ids('  ')).toHaveLength(3);
    expect(ids('no such thing')).toEqual([]);
  });

  it('shows the first sentence of a description as its one line', () => {
    expect(oneLine('Three mirrors. Then more.')).toBe('Three mirrors.');
    expect(oneLine('Fig. 4 of the paper')).toBe('Fig. 4 of the paper');
    expect(oneLine('As in Fig. 13 of the paper: a spiral. The rest.')).toBe(
      'As in Fig. 13 of the paper: a spiral.',
    );
    expect(oneLine('Angles 1.5 and 2. Then.')).toBe('Angles 1.5 and 2.');
  });
});
