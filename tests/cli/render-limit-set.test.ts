/**
 * `kleinflow render` on Fig. 6 (a quaternion Kleinian group), through the real executable: the PNG
 * is the traced picture with the limit-set dots painted over it by shader-gen/space/limit-dots-3d.ts
 * (pixel for pixel), and the dots are there.
 */
import { readFileSync } from 'node:fs';
import { join } from 'node:path';
import { describe, expect, it } from 'vitest';
import { paintSceneLimitSets3d } from '../../shader-gen/space/limit-dots-3d.ts';
import { renderScene3d } from '../../shader-gen/space/render-3d.ts';
import { decodePng } from '../../src/io/png.ts';
import { cliTempDir, evaluateFile, ROOT, runCliOk } from './run-cli.ts';

const FIG6 = join(ROOT, 'examples/3d/fig06-quaternion-kleinian-group.kleinflow.json');

const dir = cliTempDir('kleinflow-fig6-');

describe('kleinflow render on a quaternion Kleinian group', () => {
  it('paints the limit set over the traced picture', () => {
    const out = join(dir, 'fig6.png');
    runCliOk(['render', FIG6, '-o', out, '--size', '96x80', '--samples', '1']);
    const png = decodePng(readFileSync(out));
    const scene = evaluateFile(FIG6).scene3d!;
    const expected = renderScene3d(scene, 96, 80, { samples: 1 });
    const background = Buffer.from(expected.data);
    paintSceneLimitSets3d(scene, expected);
    expect(Buffer.from(png.data)).toEqual(Buffer.from(expected.data));
    let changed = 0;
    for (let i = 0; i < background.length; i += 4) if (background[i] !== png.data[i]) changed++;
    expect(changed).toBeGreaterThan(100);
  });
});
