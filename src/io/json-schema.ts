/**
 * The published JSON Schema of the Kleinflow document, generated from the zod schema that
 * validates documents (nodes/graph/document.ts), so the two cannot drift. Node params are an open
 * map here: what they mean depends on the node type and is checked when the graph is evaluated.
 * The committed copy is nodes/graph/kleinflow.schema.json (regenerate: `npx tsx src/io/write-schema.ts`).
 */
import { z } from 'zod';
import { DOC_VERSION, docSchema } from '../../nodes/graph/document.ts';

export function documentJsonSchema(): Record<string, unknown> {
  const generated = z.toJSONSchema(docSchema, { target: 'draft-2020-12' }) as Record<string, unknown>;
  const { $schema, ...rest } = generated;
  return {
    $schema,
    title: 'Kleinflow graph document',
    description: `A Kleinflow node graph (format "kleinflow", version ${DOC_VERSION}): nodes with their params, edges between named ports, and the view.`,
    ...rest,
  };
}

/** The schema as the text of the committed file (2-space indent, trailing newline). */
export const documentJsonSchemaText = (): string => `${JSON.stringify(documentJsonSchema(), null, 2)}\n`;
