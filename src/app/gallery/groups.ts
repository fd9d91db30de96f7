/**
 * The Examples gallery's sections, by example id. One table, checked by a test: every bundled
 * example sits in exactly one section, so a new example file cannot go missing from the gallery.
 */
import type { Example } from '../examples.ts';

export interface GallerySection {
  readonly title: string;
  readonly ids: readonly string[];
}

export const GALLERY_SECTIONS: readonly GallerySection[] = [
  {
    title: 'Kaleidoscopes',
    ids: [
      'kaleidoscope-333',
      'kaleidoscope-442',
      'kaleidoscope-632',
      'rectangle-2222-wallpaper',
      'rosette-k-mirror',
      'glide-reflection-frieze',
      'spherical-235',
      'hyperbolic-237',
      'modular-23inf',
    ],
  },
  {
    title: 'Kleinian and Schottky groups',
    ids: ['apollonian-gasket', 'schottky-pair', 'schottky-matrix-generators', 'spiral-similarity-pearls'],
  },
  {
    title: 'Figures from the paper',
    ids: [
      'fig02-four-kissing-disks',
      'six-disks',
      'four-disks-in-a-square',
      'fig05-limit-set',
      'fig08-hyperbolic-tessellation',
      'fig13-hyperbolic-mobius',
      'parabolic-mobius',
      'elliptic-mobius',
      'loxodromic-spiral',
      'fig22-internal-area',
      'fig23-constant-width-circles',
    ],
  },
  { title: 'Pictures', ids: ['image-kaleidoscope-245', 'seed-picture-orbit'] },
  { title: 'Animation', ids: ['animated-breathing-loxodromic', 'fig39-schottky-waltz'] },
  {
    title: '3D',
    ids: [
      'fig11-sphere-inversion-fractal',
      'fig12-eight-spheres-three-seeds',
      'fig24-orbit-of-a-cube',
      'indras-bubbles',
      'fig17-parallel-planes',
      'fig18-compound-parabolic',
      'fig19-two-sphere-generator',
      'fig20-compound-loxodromic',
    ],
  },
];

export interface GalleryGroup {
  readonly title: string;
  readonly examples: readonly Example[];
}

/** Folds a search query the way people type it: case, accents and (p,q,r) spacing don't matter. */
const fold = (s: string) =>
  s
    .normalize('NFD')
    .replace(/[\u0300-\u036f]/g, '')
    .toLowerCase()
    .replace(/\s+/g, ' ');

/**
 * The sections with the examples that match every word of `query` in their title or description
 * (empty sections dropped). Examples no section names land in "More", so none is ever hidden.
 */
export function galleryGroups(examples: readonly Example[], query = ''): GalleryGroup[] {
  const words = fold(query).split(' ').filter(Boolean);
  const matches = (e: Example) => {
    const text = fold(`${e.title} ${e.description} ${e.id}`);
    return words.every((w) => text.includes(w));
  };
  const byId = new Map(examples.map((e) => [e.id, e]));
  const placed = new Set(GALLERY_SECTIONS.flatMap((s) => s.ids));
  const sections = [
    ...GALLERY_SECTIONS.map((s) => ({
      title: s.title,
      examples: s.ids.flatMap((id) => (byId.has(id) ? [byId.get(id)!] : [])),
    })),
    { title: 'More', examples: examples.filter((e) => !placed.has(e.id)) },
  ];
  return sections
    .map((s) => ({ title: s.title, examples: s.examples.filter(matches) }))
    .filter((s) => s.examples.length > 0);
}

/**
 * The first sentence of a description, the gallery's one line: up to a full stop that is followed
 * by a capital (or the end) and does not close an abbreviation such as "Fig." or "e.g.".
 */
export function oneLine(description: string): string {
  const end = description.search(/(?<!\b(?:Fig|Figs|e\.g|i\.e|cf|vs))[.!?](?=\s+[A-Z“"(]|$)/);
  return end < 0 ? description : description.slice(0, end + 1);
}
