/**
 * Hand-written probe shaders, one per example they were written for: what a careful person would
 * write for that one scene (constants inline, no generality). The bench compares the generated
 * program's speed with these; tests/parity checks that they compute the same picture.
 */
import { readFileSync } from 'node:fs';

export interface HandWrittenShader {
  /** The example (examples/<example>.kleinflow.json) the shader hard-codes. */
  readonly example: string;
  /** The fragment shader (probe output, frame uniforms as in compile()). */
  readonly source: string;
}

const read = (file: string) => readFileSync(new URL(`./${file}`, import.meta.url), 'utf8');

export const HAND_WRITTEN: readonly HandWrittenShader[] = [
  { example: 'hyperbolic-237', source: read('hyperbolic-237.frag') },
  { example: 'apollonian-gasket', source: read('apollonian-gasket.frag') },
];
