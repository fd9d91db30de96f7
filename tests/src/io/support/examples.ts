/** The example documents as raw text (the listing is tests/support/examples.ts's, found at test time). */
import { readFileSync } from 'node:fs';
import { basename } from 'node:path';
import { exampleNames, examplePath } from '../../../../src/cli/examples.ts';

export function exampleFiles(): { name: string; text: string }[] {
  return exampleNames().map((name) => {
    const file = examplePath(name);
    return { name: basename(file), text: readFileSync(file, 'utf8') };
  });
}
