/**
 * Hand-written 3D sphere tracers, one per example, each written for speed for that one picture
 * (literals, no arrays, the bound once at the end of the walk, the tight bounding sphere, hit on the
 * seed-image distance) — not copies of the generator's program. tests/bench/trace3d.ts measures the
 * generated programs against them; tests/parity/trace3d-parity.test.ts checks they draw the same
 * picture (hit/miss).
 */
import { readFileSync } from 'node:fs';

export interface HandWrittenTracer {
  /** The 3D example (examples/3d/<example>.kleinflow.json) whose scene the shader hard-codes. */
  readonly example: string;
  /** Probe output (hit, t, depth, seed), frame uniforms as compile3d's. */
  readonly source: string;
}

const read = (file: string) => readFileSync(new URL(`./${file}`, import.meta.url), 'utf8');

export const HAND_WRITTEN_3D: readonly HandWrittenTracer[] = [
  { example: 'fig11-sphere-inversion-fractal', source: read('fig11-fast.frag') },
  { example: 'fig26-quasi-sphere', source: read('fig26-fast.frag') },
  { example: 'fig37-indras-bubbles-mirror', source: read('fig37-fast.frag') },
];

/**
 * Hand-written volume renderers (same rules: literals, no arrays, early exit), probe output
 * (1 − T, τ, samples, 0): tests/bench/volume3d.ts times the generated volume program against them;
 * tests/parity/volume3d-parity.test.ts checks they draw the same picture.
 */
export const HAND_WRITTEN_VOLUME: readonly HandWrittenTracer[] = [
  { example: 'fig10-volume-nesting-spheres', source: read('fig10-volume-fast.frag') },
];
