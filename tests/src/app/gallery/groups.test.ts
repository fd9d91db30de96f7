/** The gallery's sections hold every example exactly once, and search finds what people type. */

import { readFileSync } from 'node:fs';
import { join } from 'node:path';
import { describe, expect, it } from 'vitest';
import { declaredGroup, type Example } from '../../../../src/app/examples.ts';
import { GALLERY_SECTIONS, galleryGroups, oneLine } from '../../../../src/app/gallery/groups.ts';
import { EXAMPLES_3D_DIR, exampleNames } from '../../../../src/cli/examples.ts';

const fake = (id: string, title: string, description = '', group?: string): Example =>
  ({ id, title, description, ...(group ? { group } : {}), doc: {} }) as unknown as Example;
const examplesDir = join(import.meta.dirname, '..', '..', '..', '..', 'examples');
const metaOf = (name: string) => {
  const dir = exampleNames(EXAMPLES_3D_DIR).includes(name) ? EXAMPLES_3D_DIR : examplesDir;
  return JSON.parse(readFileSync(join(dir, `${name}.kleinflow.json`), 'utf8')).meta ?? {};
};

describe('gallery sections', () => {
  it('place every bundled example in exactly one section (the table or its own group), and name no missing file', () => {
    const ids = GALLERY_SECTIONS.flatMap((s) => s.ids);
    expect(new Set(ids).size).toBe(ids.length);
    const names = [...exampleNames(), ...exampleNames(EXAMPLES_3D_DIR)];
    expect(ids.filter((id) => !names.includes(id))).toEqual([]);
    const unplaced = names.filter((n) => !ids.includes(n) && !declaredGroup(metaOf(n)));
    expect(unplaced).toEqual([]);
  });

  it('give a group an example declares its own section, with no code change', () => {
    const groups = galleryGroups([
      fake('kaleidoscope-333', '*333'),
      fake('sphere-mirrors', 'Four sphere mirrors', '', '3D'),
      fake('brand-new', 'New one'),
      fake('hyperbolic-ball', 'Ball', '', '3D'),
    ]);
    expect(groups.map((g) => g.title)).toEqual(['Kaleidoscopes', '3D', 'More']);
    expect(groups[1].examples.map((e) => e.id)).toEqual(['sphere-mirrors', 'hyperbolic-ball']);
    expect(declaredGroup({ tags: ['Space', '3D'] })).toBe('3D');
    expect(declaredGroup({ group: 'Pictures' })).toBe('Pictures');
    expect(declaredGroup({ title: 'x' })).toBeUndefined();
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

describe('gallery search ranking', () => {
  it('puts an example titled with the figure before one that mentions it in passing', () => {
    const examples = [
      fake('seed-picture-orbit', 'Seed picture: the orbit of a picture (Fig. 11 in the plane)'),
      fake('fig110', 'Fig. 110 — not this one'),
      fake('fig11-sphere', 'Fig. 11 — the orbit of a seed sphere under six sphere inversions', '', '3D'),
      fake('about', 'Something', 'Compare Fig. 11 of the paper.'),
    ];
    const first = galleryGroups(examples, 'Fig. 11')[0].examples.map((e) => e.id);
    expect(first[0]).toBe('fig11-sphere');
    expect(galleryGroups(examples, 'fig 11')[0].examples[0].id).toBe('fig11-sphere');
  });
});
