/**
 * The layering of architecture.md: src → shader-gen → nodes, and nodes/ + shader-gen/ free of React,
 * the DOM and WebGL (they also run in the CLI and in workers). Scans the source files' imports.
 */
import { existsSync, readdirSync, readFileSync, statSync } from 'node:fs';
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

/** Each project source file's relative imports, as project-relative paths. */
function projectImports(): Map<string, string[]> {
  const deps = new Map<string, string[]>();
  for (const file of ['nodes', 'shader-gen', 'src'].flatMap((d) => filesUnder(join(ROOT, d)))) {
    const targets = importsOf(stripComments(readFileSync(file, 'utf8')))
      .filter((spec) => spec.startsWith('.'))
      .map((spec) => resolve(dirname(file), spec))
      .filter((target) => existsSync(target))
      .map((target) => relative(ROOT, target));
    deps.set(relative(ROOT, file), targets);
  }
  return deps;
}

/** Comments only (import paths are strings and must stay). */
const stripComments = (src: string) => src.replace(/\/\*[\s\S]*?\*\//g, '').replace(/\/\/.*$/gm, '');

/**
 * The import cycles: strongly connected groups of two or more files (Tarjan), each sorted, in
 * sorted order. Files in one group all import each other, directly or through the others.
 */
function importCycles(deps: ReadonlyMap<string, readonly string[]>): string[][] {
  let counter = 0;
  const index = new Map<string, number>();
  const low = new Map<string, number>();
  const stack: string[] = [];
  const onStack = new Set<string>();
  const groups: string[][] = [];
  const visit = (v: string) => {
    index.set(v, counter);
    low.set(v, counter++);
    stack.push(v);
    onStack.add(v);
    for (const w of deps.get(v) ?? []) {
      if (!index.has(w)) {
        visit(w);
        low.set(v, Math.min(low.get(v)!, low.get(w)!));
      } else if (onStack.has(w)) low.set(v, Math.min(low.get(v)!, index.get(w)!));
    }
    if (low.get(v) !== index.get(v)) return;
    const group: string[] = [];
    let w: string;
    do {
      w = stack.pop()!;
      onStack.delete(w);
      group.push(w);
    } while (w !== v);
    if (group.length > 1) groups.push(group.sort());
  };
  for (const v of deps.keys()) if (!index.has(v)) visit(v);
  return groups.sort((a, b) => a[0].localeCompare(b[0]));
}

/**
 * Cycles that existed before this test, outside src/, to be untied by whoever works on those
 * files next. They may shrink or go; no file may join them and no new cycle may appear.
 */
const KNOWN_CYCLES = [
  ['nodes/core/scene.ts', 'nodes/core/values.ts'],
  ['shader-gen/colour.ts', 'shader-gen/picture.ts', 'shader-gen/seeds.ts'],
];

describe('import cycles', () => {
  it('the detector finds groups of files that import each other, and nothing else', () => {
    const deps = new Map([
      ['a', ['b']],
      ['b', ['c']],
      ['c', ['a', 'd']],
      ['d', ['e']],
      ['e', []],
      ['f', ['f2']],
      ['f2', ['f']],
    ]);
    expect(importCycles(deps)).toEqual([
      ['a', 'b', 'c'],
      ['f', 'f2'],
    ]);
  });

  it('no module imports itself through others (none in src/; nothing new elsewhere)', () => {
    const allowed = (group: readonly string[]) =>
      KNOWN_CYCLES.some((known) => group.every((file) => known.includes(file)));
    expect(importCycles(projectImports()).filter((group) => !allowed(group))).toEqual([]);
  });
});
