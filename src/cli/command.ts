/**
 * The contract every `kleinflow` sub-command implements. main.ts parses nothing but the command
 * name; each command parses its own arguments (args.ts helps) and talks to the world only through
 * `io`, so tests and other front ends can run it without touching the real file system.
 */

export interface CliOutput {
  write(text: string): void;
  /** True when a person watches (a terminal): commands may draw live progress then. */
  readonly isTTY?: boolean;
  /**
   * Resolves once what was written has gone out (a pipe's reader caught up). Commands that write a
   * lot await it between pieces, so their memory stays bounded however slow the reader is.
   */
  drain?(): Promise<void>;
}

/** A file opened for reading in pieces. */
export interface InputFile {
  /** Its length in bytes when it is a regular file; null for a pipe or a device (length unknown). */
  readonly size: number | null;
  /** Its bytes, a piece at a time; the file is closed when the iteration ends or stops early. */
  readonly chunks: AsyncIterable<Uint8Array>;
}

export interface CliIo {
  readonly stdout: CliOutput;
  readonly stderr: CliOutput;
  /**
   * Opens a file for reading; rejects with a Node-style error (code ENOENT, EISDIR, …). Nothing
   * is read until `chunks` is iterated, so callers decide how much they take (src/io/input-limits.ts).
   */
  open(path: string): Promise<InputFile>;
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

/** The message of whatever was thrown (an Error's message, anything else as text). */
export const errorMessage = (e: unknown): string => (e instanceof Error ? e.message : String(e));
