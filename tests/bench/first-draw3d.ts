/**
 * First-draw time of every 3D example on software WebGL (part of `npm run bench`; alone:
 * `npx tsx tests/bench/first-draw3d.ts`): SwiftShader compiles a program to machine code at its
 * first draw, so the time of drawing ONE pixel with a new program is its compile time — what a
 * classroom machine without a GPU waits when an example opens or the structure changes. For each
 * example (programs with the same source counted once) the probe and the colour program; for the
 * examples with a hand-written tracer (tests/bench/hand-written/trace3d.ts, written for speed for
 * that one picture) its first draw too, as the reference. Fig. 37 took minutes before the seed
 * distances lost their early returns (docs/math-3d.md "Mirror material"). Prints figures, never
 * fails on a time.
 */
import { cameraUniforms, compile3d } from '../../shader-gen/space/compile-3d.ts';
import { GpuProbe } from '../parity/gpu-probe.ts';
import { exampleScenes3d } from '../shader-gen/space/scenes-3d.ts';
import { HAND_WRITTEN_3D } from './hand-written/trace3d.ts';
import { printTable } from './report.ts';
import { runWhenMain } from './run-when-main.ts';

export async function run(): Promise<void> {
  const gpu = await GpuProbe.open(1, 1);
  try {
    const seen = new Set<string>();
    /** ms of the first one-pixel draw of `source` (a new program), or undefined if seen already. */
    const firstDraw = async (vertex: string, source: string, uniforms: Parameters<GpuProbe['render']>[1]) => {
      if (seen.has(source)) return undefined;
      seen.add(source);
      const index = await gpu.program(vertex, source);
      const start = performance.now();
      await gpu.render(index, uniforms, { center: [0, 0], scale: 1 });
      return performance.now() - start;
    };
    const hand = new Map(HAND_WRITTEN_3D.map((h) => [h.example, h.source]));
    const rows: { name: string; probe?: number; colour?: number; hand?: number }[] = [];
    for (const [name, scene] of Object.entries(exampleScenes3d())) {
      const camera = cameraUniforms(scene.camera);
      const variant = scene.volume ? 'volume-probe' : 'probe';
      const p = compile3d(scene, { variant });
      const c = compile3d(scene);
      const handSource = hand.get(name);
      const row = {
        name,
        probe: await firstDraw(p.vertexSource, p.source, [...p.uniforms, ...camera]),
        colour: await firstDraw(c.vertexSource, c.source, [...c.uniforms, ...camera]),
        hand: handSource ? await firstDraw(p.vertexSource, handSource, camera) : undefined,
      };
      if (row.probe !== undefined || row.colour !== undefined || row.hand !== undefined) rows.push(row);
    }
    rows.sort((a, b) => (b.colour ?? b.probe ?? 0) - (a.colour ?? a.probe ?? 0));
    const ms = (x?: number) => (x === undefined ? '' : x.toFixed(0));
    console.log(
      `\nFirst draw of one pixel with a new program (its compile time), Chromium WebGL2 (${gpu.renderer}); ` +
        'hand = the hand-written probe tracer of that example, where there is one. Slowest first.\n',
    );
    printTable(
      ['example', 'probe ms', 'colour ms', 'hand probe ms'],
      rows.map((r) => [r.name, ms(r.probe), ms(r.colour), ms(r.hand)]),
    );
  } finally {
    await gpu.close();
  }
}

runWhenMain(import.meta.url, () => run());
