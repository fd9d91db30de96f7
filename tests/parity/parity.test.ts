/**
 * GPU = CPU in real Chromium (WebGL2 through SwiftShader): every example's probe program, rendered
 * at 256², agrees with the float64 interpreter at the pixel centres — same depth and escaped flag,
 * final point within the float32 error model — on every pixel whose path stays ε away from the
 * element boundaries (see compare.ts). Plus: new uniform values re-render without a new program,
 * the baked program equals the uniform one, and the hand-written bench shaders draw the same picture.
 */
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import type { Scene } from '../../nodes/core/scene.ts';
import { pixelToWorld } from '../../nodes/core/view.ts';
import { compile, shadertoySource } from '../../shader-gen/compile.ts';
import { rasterize } from '../../shader-gen/raster.ts';
import { HAND_WRITTEN, withDefines } from '../bench/hand-written/index.ts';
import { shadertoyWrapper } from '../shader-gen/support/glslang.ts';
import { HAND_MADE_SCENES } from '../shader-gen/support/scenes.ts';
import { exampleNames, loadExample, movePoint, sceneOf } from '../support/examples.ts';
import {
  COLOUR_LEVELS,
  compareColourWithCpu,
  compareImages,
  compareWithCpu,
  type ParityStats,
} from './compare.ts';
import { GpuProbe, type ProbeImage } from './gpu-probe.ts';

const SIZE = 256;
const MIN_AGREEMENT = 0.995;
/**
 * The least share of pixels compared (not within ε of a boundary), checked by compare.ts. Measured
 * at 256²: every example compares ≥ 93 % (four-disks-in-a-square; most ≥ 99 %), every hand-made
 * tiling ≥ 99.6 %.
 */
const MIN_COMPARED_EXAMPLE = 0.9;
const MIN_COMPARED_HAND_MADE = 0.95;

let gpu: GpuProbe;
type Row = Record<string, string | number>;
/** The console tables printed at the end: one row per example or scene, filled by several tests. */
const TABLES = {
  examples: {} as Record<string, Row>,
  'hand-made scenes': {} as Record<string, Row>,
  'hand-written and Shadertoy shaders': {} as Record<string, Row>,
};
type TableName = keyof typeof TABLES;
const row = (table: TableName, name: string, fields: Row) => {
  TABLES[table][name] = { ...TABLES[table][name], ...fields };
};

beforeAll(async () => {
  gpu = await GpuProbe.open(SIZE, SIZE);
});

afterAll(async () => {
  for (const [title, rows] of Object.entries(TABLES)) {
    if (Object.keys(rows).length === 0) continue;
    console.log(`\nGPU vs CPU parity, ${title} (${SIZE}², SwiftShader):`);
    console.table(rows);
  }
  await gpu?.close();
});

async function renderProbe(scene: Scene, baked = false): Promise<ProbeImage> {
  const program = compile(scene, { variant: 'probe', baked });
  const index = await gpu.program(program.vertexSource, program.source);
  return gpu.render(index, program.uniforms, scene.view);
}

const percent = (x: number) => `${(100 * x).toFixed(3)} %`;

function record(table: TableName, name: string, stats: ParityStats, image: ProbeImage) {
  row(table, name, {
    agreement: percent(stats.agreement),
    'raw (all px)': percent(stats.rawAgreement),
    compared: stats.compared,
    'excluded (near boundary)': stats.excluded,
    'depth ≠': stats.depthMismatch,
    'escaped ≠': stats.escapedMismatch,
    'final ≠': stats.finalMismatch,
    'GPU ms': Math.round(image.ms),
  });
}

describe('GPU probe program = CPU interpreter (256², pixel centres)', () => {
  const names = exampleNames();
  it('has examples to compare', () => expect(names.length).toBeGreaterThan(0));

  for (const name of names) {
    it(`${name}: ≥ ${100 * MIN_AGREEMENT} % of pixels agree`, async () => {
      const { scene } = loadExample(name);
      const image = await renderProbe(scene);
      const stats = compareWithCpu(scene, image, { minCompared: MIN_COMPARED_EXAMPLE });
      record('examples', name, stats, image);
      expect(stats.agreement).toBeGreaterThanOrEqual(MIN_AGREEMENT);
    });
  }
});

/** Not a tiling (elements thrown together for code coverage): nearly every path grazes a boundary. */
const NOT_A_TILING = new Set(['every-kind-cosine-edges-clip']);

describe('GPU = CPU for hand-made scenes (every element kind, every colouring)', () => {
  for (const [name, scene] of Object.entries(HAND_MADE_SCENES).filter(([n]) => !NOT_A_TILING.has(n))) {
    it(`${name}: ≥ ${100 * MIN_AGREEMENT} % of pixels agree (probe and colour)`, async () => {
      const image = await renderProbe(scene);
      const stats = compareWithCpu(scene, image, { minCompared: MIN_COMPARED_HAND_MADE });
      record('hand-made scenes', name, stats, image);
      const program = compile(scene);
      const colour = compareColourWithCpu(
        scene,
        await gpu.render(
          await gpu.program(program.vertexSource, program.source),
          program.uniforms,
          scene.view,
          { pictures: program.pictures },
        ),
        { minCompared: MIN_COMPARED_HAND_MADE },
      );
      row('hand-made scenes', name, {
        colour: percent(colour.agreement),
        'colour worst (levels)': colour.worstLevels,
      });
      expect(stats.agreement).toBeGreaterThanOrEqual(MIN_AGREEMENT);
      expect(colour.agreement).toBeGreaterThanOrEqual(MIN_AGREEMENT);
    });
  }
});

describe('GPU colour program = CPU colouring (one sample per pixel centre, 8-bit sRGB)', () => {
  for (const name of exampleNames()) {
    it(`${name}: ≥ ${100 * MIN_AGREEMENT} % of pixels within ±2 levels`, async () => {
      const { scene } = loadExample(name);
      const program = compile(scene);
      const index = await gpu.program(program.vertexSource, program.source);
      const image = await gpu.render(index, program.uniforms, scene.view, { pictures: program.pictures });
      const stats = compareColourWithCpu(scene, image, { minCompared: MIN_COMPARED_EXAMPLE });
      row('examples', name, { colour: percent(stats.agreement), 'colour worst (levels)': stats.worstLevels });
      expect(stats.agreement).toBeGreaterThanOrEqual(MIN_AGREEMENT);
      // Room under load: the CPU side measures each seed shape's edge distance (five formula
      // evaluations) at every step of every pixel's walk — 23 s for Fig. 43 at a load of 9.
    }, 120_000);
  }
});

describe('values are uniforms', () => {
  it('a moved point re-renders with new uniforms and the same program: no compileShader call', async () => {
    const { doc, scene } = loadExample('apollonian-gasket');
    const before = compile(scene, { variant: 'probe' });
    const moved = sceneOf(movePoint(doc, 'tAB', 0.03, -0.02));
    const after = compile(moved, { variant: 'probe' });
    expect(after.source).toBe(before.source);
    expect(after.uniforms).not.toEqual(before.uniforms);

    const index = await gpu.program(before.vertexSource, before.source);
    const first = await gpu.render(index, before.uniforms, scene.view);
    const compiles = await gpu.compileCount();
    const second = await gpu.render(index, after.uniforms, moved.view);
    expect(await gpu.compileCount()).toBe(compiles);

    const changed = 1 - compareImages(first, second).agreement;
    expect(changed).toBeGreaterThan(0.01); // the picture really changed…
    const stats = compareWithCpu(moved, second, { minCompared: MIN_COMPARED_EXAMPLE });
    expect(stats.agreement).toBeGreaterThanOrEqual(MIN_AGREEMENT); // …into the moved scene's picture
  });
});

describe('baked program = uniform program', () => {
  for (const name of ['hyperbolic-237', 'six-disks']) {
    it(`${name}: the literal and the uniform program give the same depths`, async ({ skip }) => {
      if (!exampleNames().includes(name)) skip();
      const { scene } = loadExample(name);
      const same = compareImages(await renderProbe(scene, false), await renderProbe(scene, true));
      expect(same.agreement).toBeGreaterThanOrEqual(0.999);
    });
  }
});

describe('hand-written bench shaders draw the same picture as the generated ones', () => {
  for (const shader of HAND_WRITTEN) {
    for (const values of ['constants', 'uniforms'] as const) {
      it(`${shader.example} (values as ${values})`, async () => {
        const { scene } = loadExample(shader.example);
        const generated = await renderProbe(scene);
        const program = compile(scene, { variant: 'probe' });
        const source = values === 'constants' ? shader.source : shader.uniformSource;
        const index = await gpu.program(program.vertexSource, source);
        const hand = await gpu.render(index, values === 'constants' ? [] : program.uniforms, scene.view);
        const same = compareImages(generated, hand);
        const vsCpu = compareWithCpu(scene, hand, { minCompared: MIN_COMPARED_EXAMPLE });
        row('hand-written and Shadertoy shaders', `hand-written ${shader.example} (${values})`, {
          'same as generated': percent(same.agreement),
          'vs CPU': percent(vsCpu.agreement),
          'GPU ms': Math.round(hand.ms),
          'generated GPU ms': Math.round(generated.ms),
        });
        expect(same.agreement).toBeGreaterThanOrEqual(0.999);
        expect(vsCpu.agreement).toBeGreaterThanOrEqual(MIN_AGREEMENT);
      });
    }
  }
});

describe('hand-written colour shaders draw the generated picture (the colour bench compares their speed)', () => {
  for (const shader of HAND_WRITTEN.filter((h) => h.colour)) {
    it(`${shader.example}: the baked colour program's pixels, to the float`, async () => {
      const { scene } = loadExample(shader.example);
      const baked = compile(scene, { baked: true });
      const generated = await gpu.render(await gpu.program(baked.vertexSource, baked.source), [], scene.view);
      const index = await gpu.program(baked.vertexSource, withDefines(shader.source, 'COLOUR'));
      const hand = await gpu.render(index, [], scene.view);
      let worst = 0;
      for (let i = 0; i < hand.data.length; i++)
        worst = Math.max(worst, Math.abs(hand.data[i] - generated.data[i]));
      expect(worst).toBeLessThan(1e-6);
    });
  }
});

describe('frame uniforms', () => {
  it('u_resolution + u_pixelOffset: a tile of a bigger image is that part of the image', async () => {
    const { scene } = loadExample('hyperbolic-237');
    const program = compile(scene, { variant: 'probe' });
    const index = await gpu.program(program.vertexSource, program.source);
    const frame = { resolution: [768, 512] as const, offset: [256, 128] as const };
    const image = await gpu.render(index, program.uniforms, scene.view, frame);
    const stats = compareWithCpu(scene, image, { frame, minCompared: MIN_COMPARED_EXAMPLE });
    expect(stats.agreement).toBeGreaterThanOrEqual(MIN_AGREEMENT);
    // …and not the same as the untiled picture.
    const whole = await gpu.render(index, program.uniforms, scene.view);
    expect(compareImages(image, whole).agreement).toBeLessThan(0.9);
  });

  it('u_bgAlpha: the background outside the clip disk takes it, everything else is opaque', async () => {
    const { scene } = loadExample('hyperbolic-237');
    expect(scene.clip).not.toBeNull();
    const program = compile(scene);
    const index = await gpu.program(program.vertexSource, program.source);
    const image = await gpu.render(index, program.uniforms, scene.view, { bgAlpha: 0 });
    const clip = scene.clip!;
    let transparent = 0;
    for (let py = 0; py < SIZE; py++) {
      for (let px = 0; px < SIZE; px++) {
        const [x, y] = pixelToWorld(scene.view, SIZE, SIZE, px, py);
        const r = Math.hypot(x - clip.c[0], y - clip.c[1]) / clip.r;
        const alpha = image.data[4 * (py * SIZE + px) + 3];
        if (r > 1 + 1e-5) {
          expect(alpha).toBe(0);
          transparent++;
        } else if (r < 1 - 1e-5) expect(alpha).toBe(1);
      }
    }
    expect(transparent).toBeGreaterThan(0.1 * SIZE * SIZE);
  });
});

describe('the Shadertoy version draws what the CPU renders (samples, jitter, sRGB)', () => {
  // hyperbolic-237 at one sample: shaded in sRGB with no conversion (shadesWithoutBlending).
  const cases = [{ name: 'six-disks' }, { name: 'kaleidoscope-632' }, { name: 'hyperbolic-237', samples: 1 }];
  for (const { name, samples } of cases) {
    const title = samples ? `${name} at ${samples} sample` : name;
    it(`${title}: ≥ 99 % of pixels within ±${COLOUR_LEVELS} levels of the CPU raster`, async ({ skip }) => {
      if (!exampleNames().includes(name)) skip();
      const loaded = loadExample(name).scene;
      const scene = samples ? { ...loaded, samples } : loaded;
      const index = await gpu.program(compile(scene).vertexSource, shadertoyWrapper(shadertoySource(scene)));
      const image = await gpu.render(index, [], scene.view);
      const cpu = rasterize(scene, { width: SIZE, height: SIZE });
      let agree = 0;
      for (let py = 0; py < SIZE; py++) {
        for (let px = 0; px < SIZE; px++) {
          const o = 4 * (py * SIZE + px);
          const c = 4 * ((SIZE - 1 - py) * SIZE + px); // the raster's row 0 is the top
          let worst = 0;
          for (let k = 0; k < 3; k++)
            worst = Math.max(worst, Math.abs(Math.round(image.data[o + k] * 255) - cpu.data[c + k]));
          if (worst <= COLOUR_LEVELS) agree++;
        }
      }
      row('hand-written and Shadertoy shaders', `shadertoy ${title}`, {
        'vs CPU': percent(agree / (SIZE * SIZE)),
        'GPU ms': Math.round(image.ms),
      });
      expect(agree / (SIZE * SIZE)).toBeGreaterThanOrEqual(0.99);
    });
  }
});
