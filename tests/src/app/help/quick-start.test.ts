/** The Help's quick start and the (2,3,7) example the first visit opens agree on the node's p, q, r. */
import { readFileSync } from 'node:fs';
import { join } from 'node:path';
import { expect, it } from 'vitest';
import type { GraphDoc } from '../../../../nodes/graph/document.ts';
import { registry } from '../../../../nodes/types/index.ts';
import { QUICK_START } from '../../../../src/app/help/quick-start.ts';

const root = join(import.meta.dirname, '..', '..', '..', '..');

it('names the p, q, r the first-visit example shows, and those a new Triangle kaleidoscope gets', () => {
  const doc = JSON.parse(
    readFileSync(join(root, 'examples', 'hyperbolic-237.kleinflow.json'), 'utf8'),
  ) as GraphDoc;
  const shown = doc.nodes.find((n) => n.type === 'kaleidoscope')!.params as Record<string, number>;
  const inputs = registry.get('kaleidoscope')!.inputs as Record<string, { default?: unknown }>;
  const text = QUICK_START[0].detail;
  expect(text).toContain(`${shown.p}, ${shown.q}, ${shown.r}`);
  expect(text).toContain(`${inputs.p.default}, ${inputs.q.default}, ${inputs.r.default}`);
});
