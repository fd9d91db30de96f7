import { it } from 'vitest';
import { autoBase } from '../../../shader-gen/figures/cayley.ts';
import { loadExample } from '../../support/examples.ts';
it('dbg', () => {
  const { scene } = loadExample('fig01-cayley-graph');
  console.log(JSON.stringify(scene.view), JSON.stringify(scene.clip), scene.elements.map((e) => JSON.stringify(e).slice(0, 150)).join('\n'));
  console.log(autoBase(scene, 1), autoBase(scene, 1.5));
});
