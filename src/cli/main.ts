/**
 * `kleinflow COMMAND [ARGS]`: finds the command in COMMANDS and runs it. Every failure ends as
 * readable text and an exit status, never a stack trace: CliErrors print their one line (plus
 * the command's usage for usage errors), anything unexpected prints `kleinflow: internal error: …`.
 */
import { formatBytes, INPUT_LIMITS } from '../io/input-limits.ts';
import { PNG_KEYWORD_BYTES } from '../io/png.ts';
import { type CliCommand, CliError, type CliIo, EXIT } from './command.ts';
import { COMMANDS } from './commands/index.ts';
import { printable } from './printable.ts';

const HELP_FLAGS = new Set(['--help', '-h', 'help']);

export function generalUsage(commands: readonly CliCommand[] = COMMANDS): string {
  const width = Math.max(4, ...commands.map((c) => c.name.length));
  return [
    'Usage: kleinflow COMMAND [ARGS]',
    '',
    'Kleinflow graphs from the command line: no browser and no GPU needed.',
    '',
    'Commands:',
    ...commands.map((c) => `  ${c.name.padEnd(width)}  ${c.summary}`),
    `  ${'help'.padEnd(width)}  show this text, or "kleinflow help COMMAND" for one command`,
    '',
    'Run "kleinflow COMMAND --help" for the options of a command.',
    '',
    `Limits: a graph file (JSON) at most ${formatBytes(INPUT_LIMITS.documentBytes)}, a PNG at most ${formatBytes(INPUT_LIMITS.pngBytes)}`,
    `(${INPUT_LIMITS.pngChunks.toLocaleString('en')} chunks, keywords of ${PNG_KEYWORD_BYTES} bytes, the graph inside it ${formatBytes(INPUT_LIMITS.documentBytes)});`,
    `points files are streamed (any number of points, ${formatBytes(INPUT_LIMITS.pointEntryChars)} per entry).`,
  ].join('\n');
}

/** Whether the arguments ask for help (before any "--"). */
const wantsHelp = (args: readonly string[]): boolean => {
  const end = args.indexOf('--');
  return (end < 0 ? args : args.slice(0, end)).some((a) => a === '--help' || a === '-h');
};

export async function main(argv: readonly string[], io: CliIo): Promise<number> {
  try {
    return await dispatch(argv, io);
  } catch (e) {
    try {
      io.stderr.write(
        `kleinflow: internal error: ${printable(e instanceof Error ? e.message : String(e))}\n`,
      );
    } catch {
      // stderr itself is broken: the exit status is all that is left.
    }
    return EXIT.internal;
  }
}

async function dispatch(argv: readonly string[], io: CliIo): Promise<number> {
  const [name, ...args] = argv;
  if (name === undefined) {
    io.stderr.write(`${generalUsage()}\n`);
    return EXIT.usage;
  }
  if (HELP_FLAGS.has(name)) {
    if (args.length === 0) {
      io.stdout.write(`${generalUsage()}\n`);
      return EXIT.ok;
    }
    const topic = COMMANDS.find((c) => c.name === args[0]);
    if (!topic) return unknownCommand(args[0], io);
    io.stdout.write(`${topic.usage}\n`);
    return EXIT.ok;
  }
  const command = COMMANDS.find((c) => c.name === name);
  if (!command) return unknownCommand(name, io);
  if (wantsHelp(args)) {
    io.stdout.write(`${command.usage}\n`);
    return EXIT.ok;
  }
  try {
    return await command.run(args, io);
  } catch (e) {
    if (!(e instanceof CliError)) throw e;
    io.stderr.write(`kleinflow ${command.name}: ${printable(e.message)}\n`);
    if (e.showUsage) io.stderr.write(`\n${command.usage}\n`);
    return e.status;
  }
}

function unknownCommand(name: string, io: CliIo): number {
  const hint = name.startsWith('-') ? `unknown option "${name}"` : `unknown command "${name}"`;
  io.stderr.write(`kleinflow: ${printable(hint)}\n\n${generalUsage()}\n`);
  return EXIT.usage;
}
