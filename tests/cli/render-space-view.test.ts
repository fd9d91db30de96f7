/**
 * `kleinflow render` of a 3D graph with a Sphairahedron parameter space view (Fig. 30): the PNG is
 * the sphere-traced picture with the view's panel in its lower right corner, pixel for pixel what
 * insetSpaceView draws over renderScene3d (docs/math-3d.md "The parameter-space view").
 */
import { mkdtempSync, readFileSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { insetSpaceView } from '../../nodes/geometry/space/sphairahedron-space-picture.ts';
import { evaluateGraph } from '../../nodes/graph/evaluate.ts';
import { parseDocumentText } from '../../nodes/graph/load.ts';
import { spaceViewTarget } from '../../nodes/graph/space-view.ts';
import { registry } from '../../nodes/types/index.ts';
import { renderScene3d } from '../../shader-gen/space/render-3d.ts';
import { decodePng } from '../../src/io/png.ts';
import { ROOT, runCli } from './run-cli.ts';

const FIG30 = join(ROOT, 'examples/3d/fig30-parameter-space.kleinflow.json');

let dir = '';
beforeAll(() => {
  dir = mkdtempSync(join(tmpdir(), 'kleinflow-space-view-'));
});
afterAll(() => {
  rmSync(dir, { recursive: true, force: true });
});

describe('kleinflow render with a parameter-space view', () => {
  it('draws the view as a panel in the corner of the 3D picture', () => {
    const out = join(dir, 'fig30.png');
    const run = runCli(['render', FIG30, '-o', out, '--size', '50x40', '--samples', '1', '--threads', '1']);
    expect(run.stderr).toBe('');
    expect(run.status).toBe(0);
    const png = decodePng(readFileSync(out));
    const loaded = parseDocumentText(readFileSync(FIG30, 'utf8'), registry);
    if (!loaded.ok) throw new Error('example does not load');
    const plain = renderScene3d(evaluateGraph(loaded.doc, registry).scene3d!, 50, 40, { samples: 1 });
    const withPanel = { ...plain, data: Uint8ClampedArray.from(plain.data) };
    insetSpaceView(withPanel, spaceViewTarget(loaded.doc)!);
    expect(Buffer.from(png.data)).toEqual(Buffer.from(withPanel.data));
    expect(Buffer.from(png.data)).not.toEqual(Buffer.from(plain.data));
  });
});
