/**
 * Source comments cite the repository's own docs: every `docs/X.md` named in a source file exists,
 * every section quoted after it (`docs/math.md "Length scale"`) is a heading of that page (a quote
 * in lower case may instead be a phrase of its text), no citation names a page without its `docs/` folder, and nothing
 * points at the design notes outside the repository (`shared/design`, `../shared/` in a comment).
 */
import { existsSync, readdirSync, readFileSync, statSync } from 'node:fs';
import { join, relative, resolve } from 'node:path';
import { describe, expect, it } from 'vitest';

const ROOT = resolve(import.meta.dirname, '../..');
const SCANNED = ['nodes', 'shader-gen', 'src', 'tests', 'examples'];
const SOURCE = /\.(ts|tsx|mts|js|mjs|jsx|css|html)$/;
const THIS_FILE = 'tests/docs/citations.test.ts';

function filesUnder(dir: string): string[] {
  const out: string[] = [];
  for (const name of readdirSync(dir)) {
    const p = join(dir, name);
    if (statSync(p).isDirectory()) out.push(...filesUnder(p));
    else if (SOURCE.test(name)) out.push(p);
  }
  return out;
}

interface Citation {
  readonly file: string;
  readonly doc: string;
  readonly section?: string;
}

/**
 * Comment lines joined into one line (a quote may wrap: `"by final\n   * position"`), so that a
 * quoted section is read whole.
 */
const joinCommentLines = (src: string) => src.replace(/\n[ \t]*(?:\*(?!\/)|\/\/)[ \t]?/g, ' ');

/** Every `docs/X.md` citation in a source text, with the quoted section after it if any. */
function citationsIn(file: string, src: string): Citation[] {
  const out: Citation[] = [];
  for (const m of joinCommentLines(src).matchAll(
    /\bdocs\/([\w-]+\.md)(?:[ \t]*[,:]?[ \t]*"([^"\n]{1,80})")?/g,
  ))
    out.push({ file, doc: m[1], section: m[2]?.replace(/\s+/g, ' ').trim() });
  return out;
}

/** Problems a source text has besides its citations' targets: bare page names, outside pointers. */
function strayReferences(src: string): string[] {
  const bad: string[] = [];
  for (const m of src.matchAll(/(?<![\w/.-])(math|architecture|testing|style)\.md\b/g))
    bad.push(`${m[0]} without docs/`);
  if (/shared\/design/.test(src)) bad.push('shared/design');
  for (const line of src.split('\n')) {
    const at = line.indexOf('../shared/');
    if (at < 0) continue;
    const before = line.slice(0, at);
    if (/^\s*(\*|\/\/|\/\*)/.test(line) || before.includes('//')) bad.push('../shared/ in a comment');
  }
  return bad;
}

/** A page's headings (outside code fences) and its prose, both lower-cased, spaces collapsed. */
function readDoc(path: string): { headings: Set<string>; text: string } {
  const headings = new Set<string>();
  let fenced = false;
  const text = readFileSync(path, 'utf8');
  for (const line of text.split('\n')) {
    if (line.startsWith('```')) fenced = !fenced;
    const h = !fenced && line.match(/^#{1,6}\s+(.+?)\s*$/);
    if (h) headings.add(h[1].toLowerCase());
  }
  return { headings, text: text.replace(/\s+/g, ' ').toLowerCase() };
}

/** Why a citation does not resolve, or null when it does. */
function unresolved(c: Citation, docsDir: string): string | null {
  const path = join(docsDir, c.doc);
  if (!existsSync(path)) return `${c.file}: docs/${c.doc} does not exist`;
  if (!c.section) return null;
  const { headings, text } = readDoc(path);
  const quote = c.section.toLowerCase();
  if (headings.has(quote)) return null;
  // A quote starting in lower case may be a phrase of the page rather than a section name.
  if (/^\p{Ll}/u.test(c.section) && text.includes(quote)) return null;
  return `${c.file}: docs/${c.doc} has no heading "${c.section}"`;
}

const sources = () =>
  SCANNED.flatMap((d) => filesUnder(join(ROOT, d)))
    .map((f) => ({ file: relative(ROOT, f).split(/[\\/]/).join('/'), src: readFileSync(f, 'utf8') }))
    .filter((f) => f.file !== THIS_FILE);

describe('the citation checker', () => {
  const docs = join(ROOT, 'docs');

  it('reads citations, also when the quote wraps onto the next comment line', () => {
    expect(citationsIn('a.ts', '/** see docs/math.md "Plane, view" and docs/testing.md. */')).toEqual([
      { file: 'a.ts', doc: 'math.md', section: 'Plane, view' },
      { file: 'a.ts', doc: 'testing.md', section: undefined },
    ]);
    expect(citationsIn('a.ts', '/**\n * (docs/math.md "Length\n * scale")\n */')[0].section).toBe(
      'Length scale',
    );
  });

  it('rejects missing pages and sections, bare page names and pointers outside the repository', () => {
    expect(unresolved({ file: 'a.ts', doc: 'nope.md' }, docs)).toMatch(/does not exist/);
    expect(unresolved({ file: 'a.ts', doc: 'math.md', section: 'No such section' }, docs)).toMatch(
      /no heading/,
    );
    expect(unresolved({ file: 'a.ts', doc: 'math.md', section: 'plane, view' }, docs)).toBeNull();
    // A capitalised quote is a section name: words of the page are not enough.
    expect(unresolved({ file: 'a.ts', doc: 'math.md', section: 'Closed-form' }, docs)).toMatch(/no heading/);
    expect(unresolved({ file: 'a.ts', doc: 'math.md', section: 'closed-form' }, docs)).toBeNull();
    expect(strayReferences('// the loop of math.md')).toEqual(['math.md without docs/']);
    expect(strayReferences('/* see ../shared/design/testing.md */')).toEqual([
      'shared/design',
      '../shared/ in a comment',
    ]);
    expect(strayReferences("const dir = '../shared/reference/x'; // optional fixtures")).toEqual([]);
    expect(strayReferences('// docs/math.md "Colouring"')).toEqual([]);
  });
});

describe('source comments cite docs/ that exist', () => {
  const all = sources();

  it('scans the project', () => {
    expect(all.length).toBeGreaterThan(200);
    expect(all.flatMap((f) => citationsIn(f.file, f.src)).length).toBeGreaterThan(30);
  });

  it('every cited page and quoted section exists', () => {
    const docs = join(ROOT, 'docs');
    const problems = all.flatMap((f) => citationsIn(f.file, f.src)).map((c) => unresolved(c, docs));
    expect(problems.filter((p) => p !== null)).toEqual([]);
  });

  it('no citation lacks docs/ or points outside the repository', () => {
    const problems = all.flatMap((f) => strayReferences(f.src).map((p) => `${f.file}: ${p}`));
    expect(problems).toEqual([]);
  });

  it('the README links every page in docs/', () => {
    const readme = readFileSync(join(ROOT, 'README.md'), 'utf8');
    const pages = readdirSync(join(ROOT, 'docs')).filter((n) => n.endsWith('.md'));
    expect(pages.length).toBeGreaterThanOrEqual(3);
    for (const page of pages) expect(readme).toContain(`(docs/${page})`);
  });
});
