import { it } from 'vitest';
import { autoBase } from '../../../shader-gen/figures/cayley.ts';
import { loadExample, exampleNames } from '../../support/examples.ts';
it('stability', () => {
  for (const name of ['fig01-cayley-graph', ...exampleNames().filter((n) => /237|triangle|schottky|apollon|wallpaper|p4|hyperbolic/.test(n)).slice(0, 8)]) {
    const { scene } = loadExample(name);
    const v = scene.view;
    const bases: string[] = [];
    for (const [dx, dy] of [[0, 0], [0.03, 0], [0, 0.05], [-0.07, 0.02], [0.1, -0.1], [0.2, 0.15]]) {
      const b = autoBase({ ...scene, view: { ...v, center: [v.center[0] + dx * v.scale, v.center[1] + dy * v.scale] } }, 1.5);
      bases.push(b ? `${b[0].toFixed(5)},${b[1].toFixed(5)}` : 'null');
    }
    console.log(name, new Set(bases).size, bases.join(' | '));
  }
});
