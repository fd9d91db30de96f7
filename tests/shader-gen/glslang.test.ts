/**
 * Every shader we generate is valid GLSL ES 3.00 (glslangValidator, one batch call) and uses no
 * identifier WebGL forbids: uniform, baked, probe and inspect variants of every example and of hand-made
 * scenes with every element kind and colouring mode, the Shadertoy versions, the vertex shader and
 * the hand-written bench shaders. `#line` markers make compiler errors point at the right node.
 */
import { describe, expect, it } from 'vitest';
import type { Scene } from '../../nodes/core/scene.ts';
import { type CompileOptions, compile, shadertoySource } from '../../shader-gen/compile.ts';
import { HAND_WRITTEN, withDefines } from '../bench/hand-written/index.ts';
import { exampleNames, loadExample } from '../support/examples.ts';
import {
  itPassesGlslang,
  type ShaderToCheck,
  shadertoyWrapper,
  validateShaders,
  webglIdentifierProblems,
} from './support/glslang.ts';
import { HAND_MADE_SCENES } from './support/scenes.ts';

const VARIANTS: Record<string, CompileOptions> = {
  color: { variant: 'color' },
  'color-baked': { variant: 'color', baked: true },
  probe: { variant: 'probe' },
  'probe-baked': { variant: 'probe', baked: true },
  inspect: { variant: 'inspect' },
  'inspect-baked': { variant: 'inspect', baked: true },
};

function shadersOf(name: string, scene: Scene): ShaderToCheck[] {
  const out: ShaderToCheck[] = Object.entries(VARIANTS).map(([variant, options]) => ({
    name: `${name}.${variant}`,
    source: compile(scene, options).source,
    stage: 'frag',
  }));
  out.push({ name: `${name}.shadertoy`, source: shadertoyWrapper(shadertoySource(scene)), stage: 'frag' });
  // One sample: no sample loop, and sRGB throughout where the tile blends nothing.
  const one = shadertoyWrapper(shadertoySource({ ...scene, samples: 1 }));
  out.push({ name: `${name}.shadertoy-1`, source: one, stage: 'frag' });
  return out;
}

describe('generated GLSL passes glslangValidator and WebGL identifier rules', () => {
  const examples = exampleNames();
  const shaders: ShaderToCheck[] = [
    ...examples.flatMap((name) => shadersOf(`example-${name}`, loadExample(name).scene)),
    ...Object.entries(HAND_MADE_SCENES).flatMap(([name, scene]) => shadersOf(`scene-${name}`, scene)),
    ...HAND_WRITTEN.flatMap((h) => [
      { name: `hand-written-${h.example}`, source: h.source, stage: 'frag' as const },
      { name: `hand-written-uniform-${h.example}`, source: h.uniformSource, stage: 'frag' as const },
      ...(h.colour
        ? [
            {
              name: `hand-written-colour-${h.example}`,
              source: withDefines(h.source, 'COLOUR'),
              stage: 'frag' as const,
            },
            {
              name: `hand-written-colour-srgb-${h.example}`,
              source: withDefines(h.source, 'COLOUR', 'SRGB_OUTPUT'),
              stage: 'frag' as const,
            },
          ]
        : []),
    ]),
    { name: 'vertex', source: compile(HAND_MADE_SCENES.empty).vertexSource, stage: 'vert' },
  ];

  it('covers every example, every hand-made scene and every variant', () => {
    expect(examples.length).toBeGreaterThan(0);
    expect(shaders.length).toBe(
      (examples.length + Object.keys(HAND_MADE_SCENES).length) * (Object.keys(VARIANTS).length + 2) +
        HAND_WRITTEN.reduce((n, h) => n + (h.colour ? 4 : 2), 0) +
        1,
    );
  });

  itPassesGlslang(shaders, (name) => `${name} compiles`);
});

describe('the validator and the identifier check do catch problems', () => {
  it('a broken shader is reported under its own name, not its neighbours', () => {
    const good = compile(HAND_MADE_SCENES['glide-parity']).source;
    const results = validateShaders([
      { name: 'good', source: good, stage: 'frag' },
      { name: 'bad', source: good.replace('return true;', 'return nothing;'), stage: 'frag' },
    ]);
    expect(results.get('good')).toEqual([]);
    expect(results.get('bad')!.join('\n')).toMatch(/nothing/);
  });

  it('flags identifiers WebGL forbids', () => {
    expect(webglIdentifierProblems('float a__b; vec2 webgl_x; int gl_Foo; vec4 gl_FragCoord;')).toEqual([
      'a__b',
      'webgl_x',
      'gl_Foo',
    ]);
  });
});

describe('#line markers map compiler errors to nodes', () => {
  const scene = HAND_MADE_SCENES['schottky-cosine-edges'];
  const program = compile(scene);

  it('an error inside element 2 is reported as source string 2, which lineMap names', () => {
    const broken = program.source.replace('vec4 d0 = el4;', 'vec4 d0 = oops;');
    expect(broken).not.toBe(program.source);
    const errors = validateShaders([{ name: 'broken', source: broken, stage: 'frag' }]).get('broken')!;
    const match = /ERROR: (\d+):(\d+):.*oops/.exec(errors.join('\n'));
    expect(match).not.toBeNull();
    expect(Number(match![1])).toBe(2);
    expect(program.lineMap[Number(match![1])]).toBe(scene.elements[1].nodeId);
  });

  it('an error in the template is reported with its real line number in source string 0', () => {
    const lines = program.source.split('\n');
    const target = lines.findIndex((l) => l.includes('outColor = shadeSample('));
    lines[target] = lines[target].replace('shadeSample(', 'shadeSampleMissing(');
    const errors = validateShaders([{ name: 'broken', source: lines.join('\n'), stage: 'frag' }]).get(
      'broken',
    )!;
    const match = /ERROR: 0:(\d+):.*shadeSampleMissing/.exec(errors.join('\n'));
    expect(match).not.toBeNull();
    expect(Number(match![1])).toBe(target + 1);
  });
});
