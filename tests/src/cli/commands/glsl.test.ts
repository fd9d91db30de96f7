/** `kleinflow glsl`: the real executable prints the baked shader or the Shadertoy version. */
import { mkdtempSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { afterAll, describe, expect, it } from 'vitest';
import { compile, shadertoySource } from '../../../../shader-gen/compile.ts';
import { examplePath } from '../../../../src/cli/examples.ts';
import { runCli } from '../../../cli/run-cli.ts';
import { shadertoyWrapper, validateShaders } from '../../../shader-gen/support/glslang.ts';
import { loadExample } from '../../../support/examples.ts';

const dir = mkdtempSync(join(tmpdir(), 'kleinflow-glsl-'));
afterAll(() => rmSync(dir, { recursive: true, force: true }));

const example = 'hyperbolic-237';
const graph = examplePath(example);

describe('kleinflow glsl', () => {
  it('prints the baked colour shader: the same text as compile(), valid GLSL ES 3.00', () => {
    const run = runCli(['glsl', graph]);
    expect(run.status).toBe(0);
    expect(run.stdout).toBe(compile(loadExample(example).scene, { baked: true }).source);
    expect(validateShaders([{ name: 'cli', source: run.stdout, stage: 'frag' }]).get('cli')).toEqual([]);
  });

  it('--shadertoy prints a mainImage that is valid once Shadertoy wraps it', () => {
    const run = runCli(['glsl', graph, '--shadertoy']);
    expect(run.status).toBe(0);
    expect(run.stdout).toBe(shadertoySource(loadExample(example).scene));
    const wrapped = shadertoyWrapper(run.stdout);
    expect(validateShaders([{ name: 'toy', source: wrapped, stage: 'frag' }]).get('toy')).toEqual([]);
  });

  it('--probe -o FILE writes the probe variant to the file', () => {
    const out = join(dir, 'probe.frag');
    const run = runCli(['glsl', graph, '--probe', '-o', out]);
    expect(run.status).toBe(0);
    expect(run.stdout).toBe('');
    expect(readFileSync(out, 'utf8')).toBe(
      compile(loadExample(example).scene, { baked: true, variant: 'probe' }).source,
    );
  });

  it('refuses --shadertoy with --probe (usage, exit 2) and a broken graph (exit 1, nothing printed)', () => {
    expect(runCli(['glsl', graph, '--shadertoy', '--probe']).status).toBe(2);
    const broken = join(dir, 'broken.json');
    const doc = JSON.parse(readFileSync(graph, 'utf8'));
    doc.nodes[0].type = 'no-such-node';
    writeFileSync(broken, JSON.stringify(doc));
    const run = runCli(['glsl', broken]);
    expect(run.status).toBe(1);
    expect(run.stdout).toBe('');
    expect(run.stderr).toMatch(/KF203/);
  });
});
