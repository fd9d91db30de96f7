/**
 * Assembles shader text line by line with `#line` markers: a block emitted for element i starts
 * with `#line 1 <i+1>` (the compiler then reports its errors as `ERROR: <i+1>:<line>`), and the
 * line after it restores the real position in source string 0, so template errors point to the
 * real line of the generated text.
 */
const RESUME = Symbol('resume');

export class SourceBuilder {
  private readonly lines: (string | typeof RESUME)[] = [];

  /** `markers: false` leaves the `#line` directives out (Shadertoy numbers lines itself). */
  constructor(private readonly markers = true) {}

  /** Adds lines (a multi-line string is split). */
  push(...text: string[]): this {
    for (const t of text) this.lines.push(...t.split('\n'));
    return this;
  }

  /** Adds `lines` as source string `sourceNumber`, then returns to string 0. */
  block(sourceNumber: number, lines: readonly string[]): this {
    if (this.markers) this.lines.push(`#line 1 ${sourceNumber}`, ...lines, RESUME);
    else this.lines.push(...lines);
    return this;
  }

  /** The lines, `#line` markers resolved (the line after a directive at index i is line i + 2). */
  toLines(): string[] {
    // A return to string 0 right before the next element's marker is left out.
    const kept = this.lines.filter((l, i) => l !== RESUME || !String(this.lines[i + 1]).startsWith('#line'));
    return kept.map((l, i) => (l === RESUME ? `#line ${i + 2} 0` : l));
  }

  toString(): string {
    return `${this.toLines().join('\n')}\n`;
  }
}
