/**
 * `kleinflow check GRAPH...`: every diagnostic of each graph, one per line on stdout
 * (`error KF203 nodes[2].type (node "x"): …`), a summary per file on stderr; exit 1 when any
 * graph has an error or cannot be read, 0 otherwise (warnings are allowed).
 */
import { hasErrors } from '../../../nodes/core/diagnostics.ts';
import { parseArgs } from '../args.ts';
import { type CliCommand, CliError, EXIT, usageError } from '../command.ts';
import { countBySeverity, formatDiagnostic, loadGraph } from '../load-graph.ts';

const plural = (n: number, word: string) => `${n} ${word}${n === 1 ? '' : 's'}`;

export const checkCommand: CliCommand = {
  name: 'check',
  summary: 'list the problems of one or more graphs; exit 1 on errors',
  usage: [
    'Usage: kleinflow check GRAPH [GRAPH...]',
    '',
    'Loads and evaluates each graph and prints every diagnostic, one per line:',
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
        for (const d of load.diagnostics) {
          io.stdout.write(`${prefix ? `${path}: ` : ''}${formatDiagnostic(d, load.doc)}\n`);
        }
        const n = countBySeverity(load.diagnostics);
        const summary =
          n.error + n.warning === 0 ? 'ok' : `${plural(n.error, 'error')}, ${plural(n.warning, 'warning')}`;
        io.stderr.write(`${path}: ${summary}\n`);
        if (hasErrors(load.diagnostics)) status = EXIT.failed;
      } catch (e) {
        if (!(e instanceof CliError)) throw e;
        io.stderr.write(`kleinflow check: ${e.message}\n`);
        status = EXIT.failed;
      }
    }
    return status;
  },
};
