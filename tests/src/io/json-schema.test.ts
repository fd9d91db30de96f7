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
    // A node is a $ref into $defs: a group node holds nodes of its own (the schema is recursive).
    const ref = (schema.properties as Record<string, { items: { $ref: string } }>).nodes.items.$ref;
    const defs = schema.$defs as Record<string, { required: string[]; properties: object }>;
    const node = defs[ref.replace('#/$defs/', '')];
    expect(node.required.sort()).toEqual(['id', 'params', 'position', 'type']);
    expect(Object.keys(node.properties)).toEqual(expect.arrayContaining(['muted', 'group']));
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

  it('a document with a group, a muted node, a frame and a reroute validates, and bad ones do not', () => {
    const schema = documentJsonSchema();
    const good = JSON.parse(examples[0].text);
    const inner = { id: 'c', type: 'circle', position: [0, 0], params: {} };
    const group = {
      id: 'g',
      type: 'group',
      position: [0, 0],
      params: {},
      muted: true,
      group: {
        nodes: [inner],
        edges: [],
        inputs: [{ name: 'center', targets: [{ node: 'c', port: 'center' }] }],
        outputs: [{ name: 'circle', from: { node: 'c', port: 'circle' } }],
      },
    };
    const frame = { id: 'f', title: 'Mirrors', color: '#335577', position: [0, 0], size: [300, 200] };
    const doc = { ...good, nodes: [...good.nodes, group], frames: [frame] };
    if (doc.edges[0]) doc.edges[0] = { ...doc.edges[0], via: [[10, 20]] };
    expect(checkSchema(schema, doc)).toEqual([]);
    expect(docSchema.safeParse(doc).success).toBe(true);
    const badInner = { ...group, group: { ...group.group, nodes: [{ ...inner, position: [0] }] } };
    expect(checkSchema(schema, { ...doc, nodes: [badInner] })).toContain(
      '$.nodes[0].group.nodes[0].position: too few items',
    );
    expect(checkSchema(schema, { ...doc, frames: [{ ...frame, size: [0, 1] }] })).toContain(
      '$.frames[0].size[0]: too small',
    );
  });

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
