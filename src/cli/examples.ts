/** Where the example graphs live and how they are named: examples/NAME.kleinflow.json. */
import { readdirSync } from 'node:fs';
import { basename, join, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';

const ROOT = resolve(fileURLToPath(new URL('../..', import.meta.url)));
export const EXAMPLES_DIR = join(ROOT, 'examples');
/** The rendered pictures (npm run render-examples), also shown by the README. */
export const EXAMPLES_PNG_DIR = join(EXAMPLES_DIR, 'png');
const SUFFIX = '.kleinflow.json';

/** Example names (file names without the suffix), sorted. */
export function exampleNames(dir = EXAMPLES_DIR): string[] {
  return readdirSync(dir)
    .filter((f) => f.endsWith(SUFFIX))
    .map((f) => basename(f, SUFFIX))
    .sort();
}

export const examplePath = (name: string, dir = EXAMPLES_DIR): string => join(dir, `${name}${SUFFIX}`);
