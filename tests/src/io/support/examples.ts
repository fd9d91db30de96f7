/**
 * The example documents as raw text, 2D (examples/) then 3D (examples/3d/): the listing is
 * src/cli/examples.ts's, found at test time.
 */
import { readFileSync } from 'node:fs';
import { basename } from 'node:path';
import { EXAMPLES_3D_DIR, EXAMPLES_DIR, exampleNames, examplePath } from '../../../../src/cli/examples.ts';

export function exampleFiles(): { name: string; text: string }[] {
  return [EXAMPLES_DIR, EXAMPLES_3D_DIR].flatMap((dir) =>
    exampleNames(dir).map((name) => {
      const file = examplePath(name, dir);
      return { name: basename(file), text: readFileSync(file, 'utf8') };
    }),
  );
}
