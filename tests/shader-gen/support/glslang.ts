/**
 * Offline GLSL ES validation with glslangValidator (docs/testing.md): many shaders in ONE call (about
 * 25 ms per file, most of it start-up when called per file), errors mapped back to each shader.
 */
import { spawnSync } from 'node:child_process';
import { mkdtempSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { expect, it } from 'vitest';

export interface ShaderToCheck {
  /** A unique, file-name-safe name. */
  readonly name: string;
  readonly source: string;
  readonly stage: 'frag' | 'vert';
}

/** glslangValidator's messages per shader name (empty: valid). */
export function validateShaders(shaders: readonly ShaderToCheck[]): Map<string, string[]> {
  const dir = mkdtempSync(join(tmpdir(), 'kleinflow-glslang-'));
  try {
    const results = new Map<string, string[]>();
    for (const stage of ['frag', 'vert'] as const) {
      const batch = shaders.filter((s) => s.stage === stage);
      if (batch.length === 0) continue;
      const files = batch.map((s) => {
        const file = join(dir, `${s.name}.${stage}`);
        writeFileSync(file, s.source);
        return file;
      });
      const run = spawnSync('glslangValidator', ['-S', stage, ...files], { encoding: 'utf8' });
      if (run.error)
        throw new Error(
          `glslangValidator could not run (${run.error.message}): apt-get install glslang-tools`,
        );
      // The output names each file on a line of its own, followed by that file's messages.
      let current: string[] | null = null;
      const byFile = new Map(files.map((f, i) => [f, batch[i].name]));
      for (const s of batch) results.set(s.name, []);
      for (const line of run.stdout.split('\n')) {
        const name = byFile.get(line.trim());
        if (name !== undefined) current = results.get(name)!;
        else if (current && /ERROR|WARNING/.test(line)) current.push(line.trim());
      }
      if (run.status !== 0 && batch.every((s) => results.get(s.name)!.length === 0)) {
        throw new Error(`glslangValidator failed without naming a file:\n${run.stdout}${run.stderr}`);
      }
    }
    return results;
  } finally {
    rmSync(dir, { recursive: true, force: true });
  }
}

/** Wraps Shadertoy's mainImage the way Shadertoy does, so it can be validated as a shader. */
export const shadertoyWrapper = (mainImage: string): string =>
  [
    '#version 300 es',
    'precision highp float;',
    'precision highp int;',
    'uniform vec3 iResolution;',
    'uniform float iTime;',
    // Shadertoy's four input channels (the generated code reads pictures from them).
    'uniform sampler2D iChannel0;',
    'uniform sampler2D iChannel1;',
    'uniform sampler2D iChannel2;',
    'uniform sampler2D iChannel3;',
    'out vec4 shadertoyColor;',
    mainImage,
    'void main() { mainImage(shadertoyColor, gl_FragCoord.xy); }',
    '',
  ].join('\n');

/**
 * Identifiers that glslang accepts but WebGL rejects (WebGL 2 spec §5.x): any containing `__`,
 * any starting with `webgl_` or `_webgl_`, and `gl_` names other than the built-ins we use.
 */
export function webglIdentifierProblems(source: string): string[] {
  const problems = new Set<string>();
  const code = source.replace(/\/\/.*$/gm, '').replace(/\/\*[\s\S]*?\*\//g, '');
  for (const [id] of code.matchAll(/\b[A-Za-z_]\w*\b/g)) {
    if (id.includes('__') || /^_?webgl_/i.test(id)) problems.add(id);
    if (id.startsWith('gl_') && !['gl_FragCoord', 'gl_VertexID', 'gl_Position'].includes(id))
      problems.add(id);
  }
  return [...problems];
}

/**
 * One test per shader, named by `title`: glslangValidator accepts it (one batch call for all) and
 * it breaks no WebGL identifier rule. Call inside a describe block.
 */
export function itPassesGlslang(
  shaders: readonly ShaderToCheck[],
  title: (name: string) => string = (name) => `${name} passes glslangValidator`,
): void {
  const results = validateShaders(shaders);
  for (const shader of shaders) {
    it(title(shader.name), () => {
      expect(results.get(shader.name)).toEqual([]);
      expect(webglIdentifierProblems(shader.source)).toEqual([]);
    });
  }
}
