/**
 * Hand-written probe shaders, one pair per example they were written for: what a careful person
 * would write for that one scene — once with its values as constants (no generality: the physical
 * limit, compared with the baked program) and once with them as uniforms in compile()'s `u_el`
 * layout (what a shader must do if a drag is not to recompile it: compared like for like with the
 * uniform program). A constants shader may also draw the example's picture (`colour`): the
 * colour bench (colour-ratio.ts) measures the generated colour pipeline against it. The bench
 * compares the generated programs' speed with these; tests/parity checks that they compute the
 * same picture.
 */
import { readFileSync } from 'node:fs';

export interface HandWrittenShader {
  /** The example (examples/<example>.kleinflow.json) the shader hard-codes. */
  readonly example: string;
  /** The fragment shader with the scene's values as constants (probe output, frame uniforms as in compile()). */
  readonly source: string;
  /** The same shader reading the scene's values from compile()'s uniforms (`u_el`, `u_maxIterations`). */
  readonly uniformSource: string;
  /**
   * Whether `source` also draws the example's picture (`#ifdef COLOUR`, see withDefines): then
   * the bench compares the generated colour programs with it.
   */
  readonly colour?: boolean;
}

/** `source` with `#define NAME` lines after its `#version` line (COLOUR, SRGB_OUTPUT). */
export function withDefines(source: string, ...names: string[]): string {
  const [version, ...rest] = source.split('\n');
  return [version, ...names.map((n) => `#define ${n}`), ...rest].join('\n');
}

const read = (file: string) => readFileSync(new URL(`./${file}`, import.meta.url), 'utf8');

export const HAND_WRITTEN: readonly HandWrittenShader[] = [
  {
    example: 'hyperbolic-237',
    source: read('hyperbolic-237.frag'),
    uniformSource: read('hyperbolic-237.uniform.frag'),
    colour: true,
  },
  {
    example: 'apollonian-gasket',
    source: read('apollonian-gasket.frag'),
    uniformSource: read('apollonian-gasket.uniform.frag'),
  },
];
