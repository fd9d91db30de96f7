import { readFileSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import { describe, expect, it } from 'vitest';
import { docSchema } from '../../../nodes/graph/document.ts';
import { documentJsonSchema, documentJsonSchemaText } from '../../../src/io/json-schema.ts';
import { exampleFiles } from './support/examples.ts';
import { checkSchema } from './support/mini-json-schema.ts';

const SCHEMA_FILE = fileURLToPath(new URL('../../../nodes/graph/kleinflow.schema.json', import.meta.url));

describe('published JSON Schema', () => {
  it('the committed schema file is the one generated from the zod schema', () => {
    const committed = readFileSync(SCHEMA_FILE, 'utf8');
    const fresh = documentJsonSchemaText();
    if (committed !== fresh) {
      expect.fail(
        'nodes/graph/kleinflow.schema.json is out of date with nodes/graph/document.ts: run `npx tsx src/io/write-schema.ts`',
      );
    }
  });

  it('names the same top-level fields and required keys as the document format', () => {
    const schema = documentJsonSchema();
    expect(Object.keys(schema.properties as object).sort()).toEqual(Object.keys(docSchema.shape).sort());
    expect([...(schema.required as string[])].sort()).toEqual([
      'edges',
      'format',
      'meta',
      'nodes',
      'version',
      'view',
    ]);
    expect(schema.additionalProperties).toBe(false);
    const node = (schema.properties as Record<string, { items: { required: string[] } }>).nodes.items;
    expect(node.required.sort()).toEqual(['id', 'params', 'position', 'type']);
  });

  const examples = exampleFiles();
  it('has examples to check', () => expect(examples.length).toBeGreaterThan(0));
  for (const { name, text } of examples) {
    it(`${name} validates against the schema and the zod schema`, () => {
      const value = JSON.parse(text);
      expect(checkSchema(documentJsonSchema(), value)).toEqual([]);
      expect(docSchema.safeParse(value).success).toBe(true);
    });
  }

  it('the checker rejects what the format forbids (so the example checks can fail)', () => {
    const schema = documentJsonSchema();
    const good = JSON.parse(examples[0].text);
    expect(checkSchema(schema, { ...good, extra: 1 })).toContain('$.extra: not allowed');
    expect(checkSchema(schema, { ...good, format: 'flower' })).toEqual(['$.format: expected "kleinflow"']);
    const badNode = { ...good, nodes: [{ id: 'a', type: 'point', position: [0], params: {} }] };
    expect(checkSchema(schema, badNode)).toContain('$.nodes[0].position: too few items');
    expect(checkSchema(schema, { ...good, view: { center: [0, 0], scale: 0 } })).toContain(
      '$.view.scale: too small',
    );
  });
});
