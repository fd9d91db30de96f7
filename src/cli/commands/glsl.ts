/**
 * `kleinflow glsl GRAPH [--shadertoy] [--probe] [-o FILE]`: the graph's fragment shader with every
 * value baked in (standalone GLSL ES 3.00 for WebGL2), or the Shadertoy `mainImage` version that
 * pastes into shadertoy.com unchanged. Compile notes (element or uniform limits) go to stderr.
 * A 3D graph gives the sphere-tracing shader; both come from shader-gen/standalone.ts (the editor's
 * Export menu uses it too).
 */
import { FRAME_UNIFORMS } from '../../../shader-gen/compile.ts';
import { FRAME_UNIFORMS_3D } from '../../../shader-gen/space/compile-3d.ts';
import { standaloneShader } from '../../../shader-gen/standalone.ts';
import { expectPositionals, formatOptions, type OptionSpec, parseArgs, stringOption } from '../args.ts';
import { type CliCommand, CliError, EXIT } from '../command.ts';
import { fileErrorMessage, formatDiagnostic, loadAnyScene } from '../load-graph.ts';
import { printable } from '../printable.ts';

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
    'A 3D graph (a render-3d node) gives the sphere-tracing shader; its frame uniforms are',
    ...FRAME_UNIFORMS_3D.map((u) => `  ${u.type} ${u.name}: ${u.doc}`),
    'and --probe writes vec4(hit, t, depth, seed) per pixel.',
    '',
    formatOptions(OPTIONS),
  ].join('\n'),
  async run(args, io) {
    const parsed = parseArgs(args, OPTIONS);
    const [graphPath] = expectPositionals(parsed, ['GRAPH']);
    if (parsed.options.shadertoy && parsed.options.probe) {
      throw new CliError('--shadertoy and --probe cannot be combined', EXIT.usage, true);
    }
    const { picture, doc, evaluation } = await loadAnyScene(io, graphPath);
    const flavour = parsed.options.shadertoy ? 'shadertoy' : parsed.options.probe ? 'probe' : 'webgl2';
    const { source, diagnostics } = standaloneShader(
      picture.kind === '3d' ? picture.scene3d : picture.scene,
      flavour,
    );
    for (const d of diagnostics)
      io.stderr.write(`${printable(graphPath)}: ${formatDiagnostic(d, doc, evaluation.origin)}\n`);
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
