/**
 * `kleinflow render` of a 3D graph with a Sphairahedron parameter space view (Fig. 30): the PNG is
 * the sphere-traced picture with the view's panel in its lower right corner, pixel for pixel what
 * insetSpaceView draws over renderScene3d (docs/math-3d.md "The parameter-space view").
 */
import { readFileSync } from 'node:fs';
import { join } from 'node:path';
import { describe, expect, it } from 'vitest';
import { insetSpaceView } from '../../nodes/geometry/space/sphairahedron-space-picture.ts';
import { spaceViewTarget } from '../../nodes/graph/space-view.ts';
import { renderScene3d } from '../../shader-gen/space/render-3d.ts';
import { decodePng } from '../../src/io/png.ts';
import { cliTempDir, evaluateFile, ROOT, runCliOk } from './run-cli.ts';

const FIG30 = join(ROOT, 'examples/3d/fig30-parameter-space.kleinflow.json');

const dir = cliTempDir('kleinflow-space-view-');

describe('kleinflow render with a parameter-space view', () => {
  it('draws the view as a panel in the corner of the 3D picture', () => {
    const out = join(dir, 'fig30.png');
    runCliOk(['render', FIG30, '-o', out, '--size', '50x40', '--samples', '1', '--threads', '1']);
    const png = decodePng(readFileSync(out));
    const loaded = evaluateFile(FIG30);
    const plain = renderScene3d(loaded.scene3d!, 50, 40, { samples: 1 });
    const withPanel = { ...plain, data: Uint8ClampedArray.from(plain.data) };
    insetSpaceView(withPanel, spaceViewTarget(loaded.doc)!);
    expect(Buffer.from(png.data)).toEqual(Buffer.from(withPanel.data));
    expect(Buffer.from(png.data)).not.toEqual(Buffer.from(plain.data));
  });
});
