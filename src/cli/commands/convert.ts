/**
 * `kleinflow convert INPUT [-o OUT.kleinflow.json]`: any graph Kleinflow opens — a Flower graph,
 * a Kleinflow document of an older version, a PNG exported by Kleinflow, a share link in a text
 * file — written as a current Kleinflow document (the same text the editor's Save writes).
 * Import notes (what did not carry over) go to stderr; exit 1 when the input cannot be opened.
 */
import { openBytes, serializeDocument } from '../../io/document-io.ts';
import { expectPositionals, formatOptions, type OptionSpec, parseArgs, stringOption } from '../args.ts';
import { type CliCommand, CliError, EXIT, usageError } from '../command.ts';
import { fileErrorMessage, formatDiagnostic, readInput } from '../load-graph.ts';
import { printable } from '../printable.ts';

const OPTIONS: readonly OptionSpec[] = [
  {
    long: 'output',
    short: 'o',
    value: 'FILE',
    doc: 'the .kleinflow.json to write (default: standard output)',
  },
];

const SOURCE_NAMES = {
  kleinflow: 'Kleinflow document',
  flower: 'Flower graph',
  png: 'Kleinflow PNG',
  'share-link': 'share link',
} as const;

export const convertCommand: CliCommand = {
  name: 'convert',
  summary: 'convert a Flower graph (or a PNG, share link, older document) to a Kleinflow document',
  usage: [
    'Usage: kleinflow convert INPUT [-o OUT.kleinflow.json]',
    '',
    'Reads a graph from the original Flower editor (its JSON export), a Kleinflow document (any',
    'version), a PNG exported by Kleinflow or a text file holding a share link, and writes it as',
    "a current Kleinflow document, formatted as the editor's Save writes it. What a Flower graph",
    'holds that Kleinflow cannot reproduce yet is listed on stderr (KF502 notes).',
    '',
    formatOptions(OPTIONS),
  ].join('\n'),
  async run(args, io) {
    const parsed = parseArgs(args, OPTIONS);
    const [input] = expectPositionals(parsed, ['INPUT']);
    const output = stringOption(parsed, 'output');
    if (output === input) throw usageError('the output would overwrite the input: choose another -o FILE');

    const opened = openBytes(await readInput(io, input));
    if (!opened.ok) {
      for (const d of opened.diagnostics) io.stderr.write(`${printable(input)}: ${formatDiagnostic(d)}\n`);
      throw new CliError(`"${input}" could not be converted`);
    }
    for (const d of opened.notes)
      io.stderr.write(`${printable(input)}: ${formatDiagnostic(d, opened.doc)}\n`);
    const text = serializeDocument(opened.doc);
    if (output === undefined) {
      io.stdout.write(text);
    } else {
      try {
        await io.writeFile(output, text);
      } catch (e) {
        throw new CliError(fileErrorMessage('write', output, e));
      }
    }
    const notes = opened.notes.filter((d) => d.severity !== 'info').length;
    io.stderr.write(
      `${input}: ${SOURCE_NAMES[opened.source]} → ${output ?? 'stdout'}: ${opened.doc.nodes.length} nodes, ` +
        `${opened.doc.edges.length} edges${notes ? `, ${notes} note${notes === 1 ? '' : 's'} above` : ''}\n`,
    );
    return EXIT.ok;
  },
};
