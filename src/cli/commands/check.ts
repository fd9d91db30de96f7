/**
 * `kleinflow check GRAPH...`: every diagnostic of each graph, one per line on stdout
 * (`error KF203 nodes[2].type (node "x"): …`), a summary per file on stderr; exit 1 when any
 * graph has an error or cannot be read, 0 otherwise (warnings are allowed). Besides loading and
 * evaluating, it compiles the scene's shader (as the editor does) so the GPU's own problems
 * (KF401 too many elements, KF404 uniform budget, KF405 values beyond GPU range) show too.
 */
import { type Diagnostic, hasErrors } from '../../../nodes/core/diagnostics.ts';
import { compile } from '../../../shader-gen/compile.ts';
import { parseArgs } from '../args.ts';
import { type CliCommand, CliError, EXIT, usageError } from '../command.ts';
import { countBySeverity, formatDiagnostic, type GraphLoad, loadGraph } from '../load-graph.ts';
import { printable } from '../printable.ts';

const plural = (n: number, word: string) => `${n} ${word}${n === 1 ? '' : 's'}`;

/**
 * The load's diagnostics plus those of compiling its scene (uniform variant, what the editor runs),
 * when it has elements; a compile diagnostic with the same code and text as one the evaluation
 * already gave (e.g. the render node's KF401) is not repeated.
 */
function withCompileDiagnostics(load: GraphLoad): readonly Diagnostic[] {
  const scene = load.evaluation?.scene;
  if (!scene || scene.elements.length === 0) return load.diagnostics;
  const key = (d: Diagnostic) => `${d.code} ${d.message}`;
  const seen = new Set(load.diagnostics.map(key));
  const all = [...load.diagnostics];
  for (const d of compile(scene).diagnostics) {
    if (seen.has(key(d))) continue;
    seen.add(key(d));
    all.push(d);
  }
  return all;
}

export const checkCommand: CliCommand = {
  name: 'check',
  summary: 'list the problems of one or more graphs; exit 1 on errors',
  usage: [
    'Usage: kleinflow check GRAPH [GRAPH...]',
    '',
    'Loads, evaluates and compiles each graph and prints every diagnostic, one per line:',
    '  SEVERITY CODE PATH (node "ID"): MESSAGE',
    'With several graphs each line starts with the file name. Exits 1 when any graph has an',
    'error (or cannot be read), 0 when there are at most warnings.',
  ].join('\n'),
  async run(args, io) {
    const { positionals } = parseArgs(args, []);
    if (positionals.length === 0) throw usageError('missing GRAPH (the file to check)');
    const prefix = positionals.length > 1;
    let status: number = EXIT.ok;
    for (const path of positionals) {
      try {
        const load = await loadGraph(io, path);
        const diagnostics = withCompileDiagnostics(load);
        for (const d of diagnostics) {
          io.stdout.write(
            `${prefix ? `${printable(path)}: ` : ''}${formatDiagnostic(d, load.doc, load.evaluation?.origin)}\n`,
          );
        }
        const n = countBySeverity(diagnostics);
        const summary =
          n.error + n.warning === 0 ? 'ok' : `${plural(n.error, 'error')}, ${plural(n.warning, 'warning')}`;
        io.stderr.write(`${printable(path)}: ${summary}\n`);
        if (hasErrors(diagnostics)) status = EXIT.failed;
      } catch (e) {
        if (!(e instanceof CliError)) throw e;
        io.stderr.write(`kleinflow check: ${printable(e.message)}\n`);
        status = EXIT.failed;
      }
    }
    return status;
  },
};
