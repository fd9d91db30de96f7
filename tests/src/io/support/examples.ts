/** The example documents as raw text (the listing is tests/support/examples.ts's, found at test time). */
import { readFileSync } from 'node:fs';
import { EXAMPLES_DIR, exampleNames } from '../../../support/examples.ts';

export function exampleFiles(): { name: string; text: string }[] {
  return exampleNames().map((name) => {
    const file = `${name}.kleinflow.json`;
    return { name: file, text: readFileSync(EXAMPLES_DIR + file, 'utf8') };
  });
}
