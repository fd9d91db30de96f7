/** Where the example graphs live and how they are named: examples/NAME.kleinflow.json. */
import { createHash } from 'node:crypto';
import { readdirSync, readFileSync } from 'node:fs';
import { basename, join, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';

const ROOT = resolve(fileURLToPath(new URL('../..', import.meta.url)));
export const EXAMPLES_DIR = join(ROOT, 'examples');
/** The rendered pictures (npm run render-examples), also shown by the README. */
export const EXAMPLES_PNG_DIR = join(EXAMPLES_DIR, 'png');
/** The Examples gallery's thumbnails (npm run render-examples -- --thumbnails). */
export const EXAMPLES_THUMB_DIR = join(EXAMPLES_DIR, 'thumbs');
/**
 * The 3D examples (a render-3d node): a folder of their own, so the checks of 2D pictures (CPU
 * raster, GPU parity, thumbnails from the 2D interpreter) keep to the examples they apply to.
 */
export const EXAMPLES_3D_DIR = join(EXAMPLES_DIR, '3d');
/** Which version of each example file its thumbnail was rendered from (name → SHA-256 of the file). */
export const THUMB_SOURCES = join(EXAMPLES_THUMB_DIR, 'sources.json');
const SUFFIX = '.kleinflow.json';

/** Example names (file names without the suffix), sorted. */
export function exampleNames(dir = EXAMPLES_DIR): string[] {
  return readdirSync(dir)
    .filter((f) => f.endsWith(SUFFIX))
    .map((f) => basename(f, SUFFIX))
    .sort();
}

export const examplePath = (name: string, dir = EXAMPLES_DIR): string => join(dir, `${name}${SUFFIX}`);

/** SHA-256 (hex) of an example file's bytes: what a thumbnail records as its source. */
export function exampleDigest(name: string, dir = EXAMPLES_DIR): string {
  return createHash('sha256')
    .update(readFileSync(examplePath(name, dir)))
    .digest('hex');
}

/** Every bundled example, plane and space: its name and the folder it lives in. */
export function allExamples(): { readonly name: string; readonly dir: string }[] {
  return [EXAMPLES_DIR, EXAMPLES_3D_DIR].flatMap((dir) => exampleNames(dir).map((name) => ({ name, dir })));
}
