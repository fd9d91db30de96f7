/**
 * Text from a document or a file name, made safe to print on one terminal line: control
 * characters (C0 with newline and carriage return, DEL, C1), the line separators and the bidi
 * overrides are written as escapes (`\n`, `\x1b`, `\u202e`), so a node id cannot clear the screen,
 * retitle the terminal, reorder what follows it or fake a line such as `b.json: ok`.
 */

const NAMED: Readonly<Record<string, string>> = { '\n': '\\n', '\r': '\\r', '\t': '\\t' };

// biome-ignore lint/suspicious/noControlCharactersInRegex: these are the characters it escapes
const UNSAFE = /[\u0000-\u001f\u007f-\u009f\u2028\u2029\u202a-\u202e\u2066-\u2069]/g;

const escaped = (ch: string): string => {
  const code = ch.charCodeAt(0);
  return NAMED[ch] ?? (code < 0x100 ? `\\x${code.toString(16).padStart(2, '0')}` : `\\u${code.toString(16)}`);
};

/** `s` with every character that could act on a terminal written as an escape. */
export const printable = (s: string): string => s.replace(UNSAFE, escaped);
