/**
 * The Examples gallery's sections: this table by example id, then any group an example file
 * declares itself (`meta.group`, or the tag "3d" — see examples.ts), so a new kind of example
 * (the 3D ones) gets its own section without a code change. A test checks every bundled example
 * is placed, so a new example file cannot go missing from the gallery.
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
      'colour-by-final-point',
      'modular-23inf',
    ],
  },
  {
    title: 'Kleinian and Schottky groups',
    ids: [
      'apollonian-gasket',
      'schottky-pair',
      'schottky-matrix-generators',
      'recipe-grandma-maskit',
      'maskit-slice',
      'spiral-similarity-pearls',
    ],
  },
  {
    title: 'Figures from the paper',
    ids: [
      'fig01-cayley-graph',
      'fig02-four-kissing-disks',
      'six-disks',
      'four-disks-in-a-square',
      'fig05-limit-set',
      'fig05-limit-set-depth-first',
      'fig08-hyperbolic-tessellation',
      'fig13-hyperbolic-mobius',
      'parabolic-mobius',
      'elliptic-mobius',
      'loxodromic-spiral',
      'fig22-internal-area',
      'fig23-constant-width-circles',
      'fig41-maskit-limit-set',
      'fig42-maskit-inversions',
    ],
  },
  { title: 'Pictures', ids: ['image-kaleidoscope-245', 'seed-picture-orbit', 'webcam-kaleidoscope'] },
  {
    title: 'Animation',
    ids: [
      'animated-breathing-loxodromic',
      'fig39-schottky-waltz',
      'fig40-morph',
      'fig43-tessellation-artwork',
    ],
  },
  {
    title: '3D',
    ids: [
      'fig06-quaternion-kleinian-group',
      'fig11-sphere-inversion-fractal',
      'fig10-volume-nesting-spheres',
      'fig12-eight-spheres-three-seeds',
      'fig24-orbit-of-a-cube',
      'formula-tilted-torus',
      'indras-bubbles',
      'fig37-indras-bubbles-mirror',
      'fig17-parallel-planes',
      'fig18-compound-parabolic',
      'fig19-two-sphere-generator',
      'fig20-compound-loxodromic',
      'fig25-cube-type-sphairahedron',
      'fig26-quasi-sphere',
      'fig27-tiling-steps',
      'fig30-parameter-space',
      'fig32-tunnels',
      'cake-quasi-sphere',
      'fig28-fractal-terrain',
      'fig28a-infinite-sphairahedron',
      'fig28b-tiling-step-2',
      'fig28c-tiling-step-5',
      'fig28d-tiling-step-20',
      'fig28e-fractal-terrain-small-steps',
      'fig33-quasi-sphere-rainbow',
      'fig33-quasi-sphere-warm',
      'fig33-quasi-sphere-dusk',
      'fig33-quasi-sphere-ember',
      'fig34-quasi-sphere-by-inversions',
      'fig34-quasi-sphere-by-coordinates',
      'fig34-quasi-sphere-by-distance',
      'fig34-quasi-sphere-by-argument',
      'fig36-colour-print-quasi-sphere',
      'fig38-pseudo-kleinian',
      'fig38-pseudo-kleinian-mirror',
      'orbit-cosine-palette',
      'orbit-colour-by-final-point',
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

/** `phrase` in `text` as whole words: "fig. 11" is in "fig. 11 — …", not in "fig. 110". */
function hasPhrase(text: string, phrase: string, atStart: boolean): boolean {
  for (let at = text.indexOf(phrase); at >= 0; at = text.indexOf(phrase, at + 1)) {
    const before = at === 0 || !/[\p{L}\p{N}]/u.test(text[at - 1]);
    const after = !/[\p{L}\p{N}]/u.test(text[at + phrase.length] ?? ' ');
    if (before && after && (!atStart || at === 0)) return true;
    if (atStart) return false;
  }
  return false;
}

/**
 * How well an example answers a search, best first: its title starts with the query ("Fig. 11 —
 * …" for "Fig. 11"), the title holds the query as a phrase, the title holds every word, and last
 * the description or id does. So an example about Fig. 11 beats one that mentions it in passing.
 */
export function matchRank(e: Example, query: string): number {
  // Punctuation aside: "Fig 11" and "fig. 11" both find "Fig. 11 — …".
  const bare = (t: string) =>
    fold(t)
      .replace(/[^\p{L}\p{N}*∞]+/gu, ' ')
      .trim();
  const phrase = bare(query);
  const title = bare(e.title);
  if (!phrase) return 0;
  if (hasPhrase(title, phrase, true)) return 3;
  if (hasPhrase(title, phrase, false)) return 2;
  return phrase.split(' ').every((w) => title.includes(w)) ? 1 : 0;
}

/**
 * The sections with the examples that match every word of `query` in their title or description
 * (empty sections dropped): the table's sections, then the groups examples declare (in order of
 * first appearance; a declared group with a table section's title joins it), then "More" for
 * examples neither places, so none is ever hidden. With a query, the best matches (matchRank) come
 * first in each section and the section with the best one comes first, so Enter opens it.
 */
export function galleryGroups(examples: readonly Example[], query = ''): GalleryGroup[] {
  const words = fold(query).split(' ').filter(Boolean);
  const matches = (e: Example) => {
    const text = fold(`${e.title} ${e.description} ${e.id}`);
    return words.every((w) => text.includes(w));
  };
  const byId = new Map(examples.map((e) => [e.id, e]));
  const tabled = new Set(GALLERY_SECTIONS.flatMap((s) => s.ids));
  const sections = new Map<string, Example[]>(
    GALLERY_SECTIONS.map((s) => [s.title, s.ids.flatMap((id) => (byId.has(id) ? [byId.get(id)!] : []))]),
  );
  const more: Example[] = [];
  for (const e of examples) {
    if (tabled.has(e.id)) continue;
    if (!e.group) more.push(e);
    else sections.set(e.group, [...(sections.get(e.group) ?? []), e]);
  }
  sections.set('More', [...(sections.get('More') ?? []), ...more]);
  const rank = new Map(examples.map((e) => [e, matchRank(e, query)]));
  const best = (list: readonly Example[]) => Math.max(...list.map((e) => rank.get(e)!));
  return [...sections]
    .map(([title, list]) => ({
      title,
      examples: list.filter(matches).sort((a, b) => rank.get(b)! - rank.get(a)!),
    }))
    .filter((s) => s.examples.length > 0)
    .sort((a, b) => best(b.examples) - best(a.examples));
}

/**
 * The first sentence of a description, the gallery's one line: up to a full stop that is followed
 * by a capital (or the end) and does not close an abbreviation such as "Fig." or "e.g.".
 */
export function oneLine(description: string): string {
  const end = description.search(/(?<!\b(?:Fig|Figs|e\.g|i\.e|cf|vs))[.!?](?=\s+[A-Z“"(]|$)/);
  return end < 0 ? description : description.slice(0, end + 1);
}
