/**
 * `kleinflow glsl GRAPH [--shadertoy] [--probe] [-o FILE]`: the graph's fragment shader with every
 * value baked in (standalone GLSL ES 3.00 for WebGL2), or the Shadertoy `mainImage` version that
 * pastes into shadertoy.com unchanged. Compile notes (element or uniform limits) go to stderr.
 */
import { compile, FRAME_UNIFORMS, shadertoySource } from '../../../shader-gen/compile.ts';
import { expectPositionals, formatOptions, type OptionSpec, parseArgs, stringOption } from '../args.ts';
import { type CliCommand, CliError, EXIT } from '../command.ts';
import { fileErrorMessage, formatDiagnostic, loadScene } from '../load-graph.ts';

const OPTIONS: readonly OptionSpec[] = [
  { long: 'shadertoy', doc: 'print the Shadertoy version (mainImage, jittered samples, sRGB output)' },
  { long: 'probe', doc: 'print the probe variant: vec4(depth, final.x, final.y, escaped) per pixel' },
  { long: 'output', short: 'o', value: 'FILE', doc: 'write the shader to FILE instead of stdout' },
];

export const glslCommand: CliCommand = {
  name: 'glsl',
  summary: 'print the graph as one GLSL shader (values baked in), or for Shadertoy',
  usage: [
    'Usage: kleinflow glsl GRAPH [--shadertoy | --probe] [-o FILE]',
    '',
    'Prints the fragment shader of the graph with every value written into the code: a',
    'standalone GLSL ES 3.00 shader for WebGL2 that outputs linear RGBA for one sample. Draw a',
    'full-screen triangle with it and set the frame uniforms:',
    ...FRAME_UNIFORMS.map((u) => `  ${u.type} ${u.name}: ${u.doc}`),
    'With --shadertoy it prints a mainImage() that pastes into shadertoy.com unchanged: the',
    "graph's view and samples per pixel, averaged and converted to sRGB.",
    '',
    formatOptions(OPTIONS),
  ].join('\n'),
  async run(args, io) {
    const parsed = parseArgs(args, OPTIONS);
    const [graphPath] = expectPositionals(parsed, ['GRAPH']);
    if (parsed.options.shadertoy && parsed.options.probe) {
      throw new CliError('--shadertoy and --probe cannot be combined', EXIT.usage, true);
    }
    const { scene, doc } = await loadScene(io, graphPath);
    let source: string;
    if (parsed.options.shadertoy) source = shadertoySource(scene);
    else {
      const program = compile(scene, { baked: true, variant: parsed.options.probe ? 'probe' : 'color' });
      for (const d of program.diagnostics) io.stderr.write(`${graphPath}: ${formatDiagnostic(d, doc)}\n`);
      source = program.source;
    }
    const output = stringOption(parsed, 'output');
    if (output === undefined) io.stdout.write(source);
    else {
      try {
        await io.writeFile(output, source);
      } catch (e) {
        throw new CliError(fileErrorMessage('write', output, e));
      }
    }
    return EXIT.ok;
  },
};
