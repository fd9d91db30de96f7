/**
 * `kleinflow render` on Fig. 6 (a quaternion Kleinian group), through the real executable: the PNG
 * is the traced picture with the limit-set dots painted over it by shader-gen/space/limit-dots-3d.ts
 * (pixel for pixel), and the dots are there.
 */
import { mkdtempSync, readFileSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { evaluateGraph } from '../../nodes/graph/evaluate.ts';
import { parseDocumentText } from '../../nodes/graph/load.ts';
import { registry } from '../../nodes/types/index.ts';
import { paintSceneLimitSets3d } from '../../shader-gen/space/limit-dots-3d.ts';
import { renderScene3d } from '../../shader-gen/space/render-3d.ts';
import { decodePng } from '../../src/io/png.ts';
import { ROOT, runCli } from './run-cli.ts';

const FIG6 = join(ROOT, 'examples/3d/fig06-quaternion-kleinian-group.kleinflow.json');

let dir = '';
beforeAll(() => {
  dir = mkdtempSync(join(tmpdir(), 'kleinflow-fig6-'));
});
afterAll(() => {
  rmSync(dir, { recursive: true, force: true });
});

describe('kleinflow render on a quaternion Kleinian group', () => {
  it('paints the limit set over the traced picture', () => {
    const out = join(dir, 'fig6.png');
    const run = runCli(['render', FIG6, '-o', out, '--size', '96x80', '--samples', '1']);
    expect(run.stderr).toBe('');
    expect(run.status).toBe(0);
    const png = decodePng(readFileSync(out));
    const loaded = parseDocumentText(readFileSync(FIG6, 'utf8'), registry);
    if (!loaded.ok) throw new Error('example does not load');
    const scene = evaluateGraph(loaded.doc, registry).scene3d!;
    const expected = renderScene3d(scene, 96, 80, { samples: 1 });
    const background = Buffer.from(expected.data);
    paintSceneLimitSets3d(scene, expected);
    expect(Buffer.from(png.data)).toEqual(Buffer.from(expected.data));
    let changed = 0;
    for (let i = 0; i < background.length; i += 4) if (background[i] !== png.data[i]) changed++;
    expect(changed).toBeGreaterThan(100);
  });
});
