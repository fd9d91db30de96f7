/** The bundled examples (examples/*.kleinflow.json), by title, and the one the first run opens. */
import type { GraphDoc } from '../../nodes/graph/document.ts';
import { loadDocument } from '../../nodes/graph/load.ts';
import { registry } from '../../nodes/types/index.ts';
import { tidyIfOverlapping } from '../editor/layout.ts';

export interface Example {
  readonly id: string;
  readonly title: string;
  readonly description: string;
  readonly doc: GraphDoc;
}

// 3D examples live in examples/3d/ (see src/cli/examples.ts); their ids are their file names too.
const modules = import.meta.glob(['../../examples/*.kleinflow.json', '../../examples/3d/*.kleinflow.json'], {
  eager: true,
  import: 'default',
});

/** Examples that load cleanly, sorted by title (a broken example file is skipped, never shown). */
export const EXAMPLES: readonly Example[] = Object.entries(modules)
  .flatMap(([path, json]) => {
    const loaded = loadDocument(json, registry);
    if (!loaded.ok) return [];
    const id = path.replace(/^.*\//, '').replace(/\.kleinflow\.json$/, '');
    const { title, description } = loaded.doc.meta;
    // Example files may place nodes tighter than the editor draws them: spread them out.
    return [
      {
        id,
        title: title ?? id,
        description: description ?? '',
        doc: tidyIfOverlapping(loaded.doc, registry),
      },
    ];
  })
  .sort((a, b) => a.title.localeCompare(b.title));

export const DEFAULT_EXAMPLE_ID = 'hyperbolic-237';

export function defaultExample(): Example | undefined {
  return EXAMPLES.find((e) => e.id === DEFAULT_EXAMPLE_ID) ?? EXAMPLES[0];
}
