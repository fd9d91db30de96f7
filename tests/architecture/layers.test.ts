/**
 * The layering of architecture.md: src → shader-gen → nodes, and nodes/ + shader-gen/ free of React,
 * the DOM and WebGL (they also run in the CLI and in workers); shader-gen/'s modules free of import
 * circles. Scans the source files' imports.
 */
import { readdirSync, readFileSync, statSync } from 'node:fs';
import { dirname, join, relative, resolve } from 'node:path';
import { describe, expect, it } from 'vitest';

const ROOT = resolve(import.meta.dirname, '../..');
const SOURCE = /\.(ts|tsx|mts|js|mjs|jsx)$/;

function filesUnder(dir: string): string[] {
  const out: string[] = [];
  for (const name of readdirSync(dir)) {
    const p = join(dir, name);
    if (statSync(p).isDirectory()) out.push(...filesUnder(p));
    else if (SOURCE.test(name)) out.push(p);
  }
  return out;
}

/**
 * Removes comments and the contents of '…' / "…" strings (keeping template literals, whose text is
 * generated GLSL), so that words in comments and import paths are not mistaken for code.
 */
function stripCommentsAndStrings(src: string): string {
  let out = '';
  let i = 0;
  while (i < src.length) {
    const c = src[i];
    const next = src[i + 1];
    if (c === '/' && next === '/') {
      while (i < src.length && src[i] !== '\n') i++;
    } else if (c === '/' && next === '*') {
      const end = src.indexOf('*/', i + 2);
      i = end < 0 ? src.length : end + 2;
      out += ' ';
    } else if (c === "'" || c === '"') {
      i++;
      while (i < src.length && src[i] !== c && src[i] !== '\n') i += src[i] === '\\' ? 2 : 1;
      i++;
      out += `${c}${c}`;
    } else if (c === '`') {
      // copy the template literal verbatim (its ${…} parts are code and stay visible)
      let j = i + 1;
      while (j < src.length && src[j] !== '`') j += src[j] === '\\' ? 2 : 1;
      out += src.slice(i, j + 1);
      i = j + 1;
    } else {
      out += c;
      i++;
    }
  }
  return out;
}

/** Module specifiers of static imports, re-exports, dynamic imports and require calls. */
function importsOf(src: string): string[] {
  const specs: string[] = [];
  const patterns = [
    /\bimport\s+(?:type\s+)?[^'";]*?\bfrom\s*['"]([^'"]+)['"]/g,
    /\bexport\s+(?:type\s+)?[^'";]*?\bfrom\s*['"]([^'"]+)['"]/g,
    /\bimport\s*['"]([^'"]+)['"]/g,
    /\bimport\s*\(\s*['"]([^'"]+)['"]\s*\)/g,
    /\brequire\s*\(\s*['"]([^'"]+)['"]\s*\)/g,
  ];
  for (const re of patterns) for (const m of src.matchAll(re)) specs.push(m[1]);
  return specs;
}

/** Which top-level folder a relative import lands in ('' for packages). */
const layerOf = (file: string, spec: string) =>
  spec.startsWith('.') ? relative(ROOT, resolve(dirname(file), spec)).split(/[\\/]/)[0] : '';

const UI_PACKAGES = /^(react|react-dom|@xyflow\/|playwright|jsdom)(\/|$)/;
const DOM_GLOBALS = /(?<![\w$.])(document|window)\s*\.|\bWebGL2RenderingContext\b/;

interface Violation {
  file: string;
  what: string;
}

function check(dir: 'nodes' | 'shader-gen' | 'src'): Violation[] {
  const bad: Violation[] = [];
  for (const file of filesUnder(join(ROOT, dir))) {
    const rel = relative(ROOT, file);
    const src = readFileSync(file, 'utf8');
    for (const spec of importsOf(src)) {
      const layer = layerOf(file, spec);
      if (dir === 'nodes' && (layer === 'shader-gen' || layer === 'src')) bad.push({ file: rel, what: spec });
      if (dir === 'shader-gen' && layer === 'src') bad.push({ file: rel, what: spec });
      if (dir !== 'src' && UI_PACKAGES.test(spec)) bad.push({ file: rel, what: spec });
      if (dir !== 'src' && /^node:|^(fs|path|child_process|os)$/.test(spec))
        bad.push({ file: rel, what: spec });
    }
    if (dir !== 'src') {
      const code = stripCommentsAndStrings(src);
      const m = code.match(DOM_GLOBALS);
      if (m) bad.push({ file: rel, what: m[0] });
    }
  }
  return bad;
}

describe('the scanner', () => {
  it('finds every kind of import and ignores comments and strings', () => {
    const src = `import a from './a.ts';\nimport type { B } from "../b.ts";\nexport { c } from './c.ts';\nimport './side.ts';\nconst d = await import('./d.ts');\nimport {\n  e,\n  f,\n} from 'react';`;
    expect(importsOf(src).sort()).toEqual(['../b.ts', './a.ts', './c.ts', './d.ts', './side.ts', 'react']);
    const code = stripCommentsAndStrings(
      `// window.open\n/* document.body */ const s = './document.ts'; x = window.innerWidth;`,
    );
    expect(code.match(DOM_GLOBALS)?.[0]).toBe('window.');
    expect(
      stripCommentsAndStrings('// document.title\nconst p = "document.ts";').match(DOM_GLOBALS),
    ).toBeNull();
  });

  it('sees the project files', () => {
    expect(filesUnder(join(ROOT, 'nodes')).length).toBeGreaterThan(20);
    expect(filesUnder(join(ROOT, 'shader-gen')).length).toBeGreaterThan(5);
    const imports = filesUnder(join(ROOT, 'nodes')).flatMap((f) => importsOf(readFileSync(f, 'utf8')));
    expect(imports.length).toBeGreaterThan(40);
  });
});

describe('layers (src → shader-gen → nodes)', () => {
  it('nodes/ imports nothing from shader-gen/ or src/, no UI packages, no Node built-ins, no DOM or WebGL', () => {
    expect(check('nodes')).toEqual([]);
  });

  it('shader-gen/ imports nothing from src/, no UI packages, no Node built-ins, no DOM or WebGL', () => {
    expect(check('shader-gen')).toEqual([]);
  });

  it('src/ imports resolve inside the project layers', () => {
    // src may use everything below it; this only checks that relative imports stay in the tree
    for (const v of check('src')) expect(v).toBeUndefined();
    for (const file of filesUnder(join(ROOT, 'src'))) {
      for (const spec of importsOf(readFileSync(file, 'utf8'))) {
        if (spec.startsWith('.'))
          expect(['src', 'nodes', 'shader-gen', 'examples']).toContain(layerOf(file, spec));
      }
    }
  });
});

/** The first circle in a graph of imports (file → files it imports), closing where it began; or null. */
function firstCircle(deps: ReadonlyMap<string, readonly string[]>): string[] | null {
  const done = new Set<string>();
  const path: string[] = [];
  const visit = (f: string): string[] | null => {
    const at = path.indexOf(f);
    if (at >= 0) return [...path.slice(at), f];
    if (done.has(f)) return null;
    path.push(f);
    for (const d of deps.get(f) ?? []) {
      const circle = visit(d);
      if (circle) return circle;
    }
    path.pop();
    done.add(f);
    return null;
  };
  for (const f of deps.keys()) {
    const circle = visit(f);
    if (circle) return circle;
  }
  return null;
}

/** The imports among the files under `dir` (type imports included), paths from ROOT. */
function importGraph(dir: string): Map<string, string[]> {
  const files = new Set(filesUnder(join(ROOT, dir)));
  return new Map(
    [...files].map((f) => [
      relative(ROOT, f),
      importsOf(readFileSync(f, 'utf8'))
        .filter((spec) => spec.startsWith('.'))
        .map((spec) => resolve(dirname(f), spec))
        .filter((target) => files.has(target))
        .map((target) => relative(ROOT, target)),
    ]),
  );
}

describe('import circles', () => {
  it('the search finds a circle, and only where there is one', () => {
    const graph = (edges: Record<string, string[]>) => new Map(Object.entries(edges));
    expect(firstCircle(graph({ a: ['b'], b: ['c'], c: ['a'] }))).toEqual(['a', 'b', 'c', 'a']);
    expect(firstCircle(graph({ a: ['b', 'c'], b: ['c'], c: [] }))).toBeNull();
  });

  it('shader-gen/ has none (the sRGB helpers live in srgb.ts, used by colour, picture and seeds)', () => {
    const graph = importGraph('shader-gen');
    expect(graph.get('shader-gen/colour.ts')).toContain('shader-gen/srgb.ts');
    expect(firstCircle(graph)).toBeNull();
  });
});
