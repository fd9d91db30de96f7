/**
 * Golden sources: the exact text compile() produces for three small hand-made scenes (and one
 * Shadertoy version), stored under golden/. A change to the generator shows up here as a diff to
 * read. After an intended change, rewrite them with `UPDATE_GOLDEN=1 npx vitest run
 * tests/shader-gen/compile-golden.test.ts` and review the diff before committing.
 */
import { existsSync, readFileSync, writeFileSync } from 'node:fs';
import { describe, expect, it } from 'vitest';
import { compile, shadertoySource } from '../../shader-gen/compile.ts';
import { HAND_MADE_SCENES } from './support/scenes.ts';

const GOLDEN_DIR = new URL('./golden/', import.meta.url);
const UPDATE = process.env.UPDATE_GOLDEN === '1';

const CASES: readonly { file: string; source: () => string }[] = [
  {
    file: 'triangle-333-parity-clip.color.frag',
    source: () => compile(HAND_MADE_SCENES['triangle-333-parity-clip']).source,
  },
  {
    file: 'schottky-cosine-edges.color-baked.frag',
    source: () => compile(HAND_MADE_SCENES['schottky-cosine-edges'], { baked: true }).source,
  },
  {
    file: 'strips-hsv-edges.probe.frag',
    source: () => compile(HAND_MADE_SCENES['strips-hsv-edges'], { variant: 'probe' }).source,
  },
  {
    file: 'schottky-seeds-fill-edges.color.frag',
    source: () => compile(HAND_MADE_SCENES['schottky-seeds-fill-edges']).source,
  },
  {
    file: 'triangle-333-picture.color.frag',
    source: () => compile(HAND_MADE_SCENES['triangle-333-picture']).source,
  },
  {
    file: 'triangle-333-parity-clip.shadertoy.glsl',
    source: () => shadertoySource(HAND_MADE_SCENES['triangle-333-parity-clip']),
  },
  {
    // One sample of a tile that blends nothing: shaded in sRGB, written without any conversion.
    file: 'triangle-333-parity-clip.shadertoy-1.glsl',
    source: () => shadertoySource({ ...HAND_MADE_SCENES['triangle-333-parity-clip'], samples: 1 }),
  },
];

describe('generated sources match the golden files', () => {
  for (const { file, source } of CASES) {
    it(file, () => {
      const path = new URL(file, GOLDEN_DIR);
      const actual = source();
      if (UPDATE) writeFileSync(path, actual);
      if (!existsSync(path))
        throw new Error(`golden/${file} is missing: run with UPDATE_GOLDEN=1 to create it`);
      expect(actual).toBe(readFileSync(path, 'utf8'));
    });
  }
});
