/**
 * The contract every `kleinflow` sub-command implements. main.ts parses nothing but the command
 * name; each command parses its own arguments (args.ts helps) and talks to the world only through
 * `io`, so tests and other front ends can run it without touching the real file system.
 */

export interface CliOutput {
  write(text: string): void;
  /** True when a person watches (a terminal): commands may draw live progress then. */
  readonly isTTY?: boolean;
}

export interface CliIo {
  readonly stdout: CliOutput;
  readonly stderr: CliOutput;
  /** Reads a whole file as bytes; rejects with a Node-style error (code ENOENT, EISDIR, …). */
  readFile(path: string): Promise<Uint8Array>;
  writeFile(path: string, data: Uint8Array | string): Promise<void>;
}

/** Exit statuses shared by every command. */
export const EXIT = {
  ok: 0,
  /** The graph or an input file has problems (diagnostics were printed). */
  failed: 1,
  /** The command line itself is wrong (usage was printed). */
  usage: 2,
  /** A bug in Kleinflow (sysexits' EX_SOFTWARE). */
  internal: 70,
} as const;

export interface CliCommand {
  readonly name: string;
  /** One line for the command list in `kleinflow help`. */
  readonly summary: string;
  /** The full usage text: synopsis line(s), then options. */
  readonly usage: string;
  /** Runs the command; resolves to the process exit status. Expected failures never throw. */
  run(args: readonly string[], io: CliIo): Promise<number>;
}

/**
 * A problem the user can fix (bad argument, unreadable file): the command prints the message,
 * with the usage text when `usage` is set, and exits with `status`. Thrown by shared helpers so a
 * command's happy path stays linear; main.ts and runCommand turn it into output.
 */
export class CliError extends Error {
  constructor(
    message: string,
    readonly status: number = EXIT.failed,
    readonly showUsage = false,
  ) {
    super(message);
    this.name = 'CliError';
  }
}

export const usageError = (message: string): CliError => new CliError(message, EXIT.usage, true);
