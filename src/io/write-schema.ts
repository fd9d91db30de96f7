/**
 * Writes nodes/graph/kleinflow.schema.json from the zod document schema. Run after changing
 * nodes/graph/document.ts: `npx tsx src/io/write-schema.ts` (a test fails until the file matches).
 */
import { writeFileSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import { documentJsonSchemaText } from './json-schema.ts';

const SCHEMA_FILE = fileURLToPath(new URL('../../nodes/graph/kleinflow.schema.json', import.meta.url));

writeFileSync(SCHEMA_FILE, documentJsonSchemaText());
console.log(`wrote ${SCHEMA_FILE}`);
