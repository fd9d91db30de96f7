/**
 * The layering of docs/architecture.md "Layers": src → shader-gen → nodes, nodes/ and shader-gen/
 * free of React, the DOM, WebGL and Node built-ins (they run in the CLI and in the browser), and the
 * folder rules inside src/. The checker is first shown to catch made-up offenders, then run on
 * every source file of the project.
 */
import { existsSync, readdirSync, readFileSync, statSync } from 'node:fs';
import { dirname, join, relative, resolve } from 'node:path';
import { describe, expect, it } from 'vitest';
import {
  checkFile,
  checkFiles,
  DOM_GLOBALS,
  importsOf,
  repoPath,
  type SourceFile,
  SRC_RULES,
  stripCommentsAndStrings,
} from './layer-rules.ts';

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

const project = (dir: string): SourceFile[] =>
  filesUnder(join(ROOT, dir)).map((f) => ({ path: repoPath(ROOT, f), source: readFileSync(f, 'utf8') }));

/** The rules each made-up file breaks (by rule text), [] when it is clean. */
const rulesBroken = (path: string, source: string) => checkFile({ path, source }).map((v) => v.rule);

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
    expect(project('nodes').length).toBeGreaterThan(20);
    expect(project('shader-gen').length).toBeGreaterThan(5);
    const src = project('src');
    for (const folder of ['app', 'editor', 'viewport', 'state', 'io', 'cli'])
      expect(src.filter((f) => f.path.startsWith(`src/${folder}/`)).length).toBeGreaterThan(3);
    const imports = project('nodes').flatMap((f) => importsOf(f.source));
    expect(imports.length).toBeGreaterThan(40);
  });
});

describe('the checker catches made-up offenders', () => {
  it('in nodes/ and shader-gen/', () => {
    expect(
      rulesBroken('nodes/geometry/x.ts', `import { compile } from '../../shader-gen/compile.ts';`),
    ).toEqual(['nodes/ imports only nodes/']);
    expect(rulesBroken('nodes/types/x.ts', `import { store } from '../../src/state/store.ts';`)).toEqual([
      'nodes/ imports only nodes/',
    ]);
    expect(
      rulesBroken('shader-gen/elements/x.ts', `export { v } from '../../src/viewport/viewport.ts';`),
    ).toEqual(['shader-gen/ never imports src/']);
    expect(rulesBroken('shader-gen/x.ts', `import { useState } from 'react';`)).toEqual([
      'shader-gen/ has no UI packages',
    ]);
    expect(rulesBroken('nodes/core/x.ts', `const { Handle } = await import('@xyflow/react');`)).toEqual([
      'nodes/ has no UI packages',
    ]);
    expect(rulesBroken('nodes/core/x.ts', `import { readFileSync } from 'node:fs';`)).toEqual([
      'nodes/ runs in the browser too: no Node built-ins',
    ]);
    expect(rulesBroken('shader-gen/x.ts', 'const gl = canvas.getContext("webgl2");')).toEqual([
      'shader-gen/ uses no DOM or WebGL',
    ]);
    expect(rulesBroken('nodes/x.ts', 'export const w = () => window.innerWidth;')).toEqual([
      'nodes/ uses no DOM or WebGL',
    ]);
    expect(rulesBroken('nodes/x.ts', 'let g: WebGL2RenderingContext;')).toEqual([
      'nodes/ uses no DOM or WebGL',
    ]);
  });

  it('in src/, folder by folder', () => {
    expect(rulesBroken('src/viewport/x.ts', `import { store } from '../state/store.ts';`)).toEqual([
      'src/viewport/ may not import src/state/',
    ]);
    expect(rulesBroken('src/editor/x.tsx', `import { App } from '../app/App.tsx';`)).toEqual([
      'src/editor/ may not import src/app/',
    ]);
    expect(
      rulesBroken('src/cli/commands/x.ts', `import { Viewport } from '../../viewport/viewport.ts';`),
    ).toEqual(['src/cli/ may not import src/viewport/']);
    expect(rulesBroken('src/io/x.ts', `import { createRoot } from 'react-dom/client';`)).toEqual([
      'src/io/ has no UI packages',
    ]);
    expect(rulesBroken('src/cli/x.ts', 'const a = document.createElement("a");')).toEqual([
      'src/cli/ uses no DOM or WebGL',
    ]);
    expect(rulesBroken('src/newfolder/x.ts', '')).toEqual(['a src/ folder with no rule in SRC_RULES']);
    expect(rulesBroken('src/app/x.ts', `import a from '../../../elsewhere/a.ts';`)).toEqual([
      'a relative import leaves the code folders',
    ]);
  });

  it('and lets allowed imports and mere mentions pass', () => {
    expect(
      rulesBroken('src/app/x.tsx', `import { Viewport } from '../viewport/viewport.ts';\nimport 'react';`),
    ).toEqual([]);
    expect(
      rulesBroken(
        'src/cli/x.ts',
        `import { readFile } from 'node:fs/promises';\nimport { p } from '../io/png.ts';`,
      ),
    ).toEqual([]);
    expect(rulesBroken('src/main.tsx', `import { App } from './app/App.tsx';`)).toEqual([]);
    expect(
      rulesBroken('nodes/x.ts', `// import React from 'react'; window.open()\nconst s = 'document.title';`),
    ).toEqual([]);
  });
});

describe('layers (src → shader-gen → nodes)', () => {
  it('nodes/ imports nothing from shader-gen/ or src/, no UI packages, no Node built-ins, no DOM or WebGL', () => {
    expect(checkFiles(project('nodes'))).toEqual([]);
  });

  it('shader-gen/ imports nothing from src/, no UI packages, no Node built-ins, no DOM or WebGL', () => {
    expect(checkFiles(project('shader-gen'))).toEqual([]);
  });

  it('src/ folders import only what their rule allows; cli/ and io/ run without a browser', () => {
    expect(Object.keys(SRC_RULES).length).toBeGreaterThan(5);
    expect(checkFiles(project('src'))).toEqual([]);
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
 * Cycles allowed to remain (none: the sRGB circle colour ↔ picture ↔ seeds went with
 * shader-gen/srgb.ts, and scene ↔ values with values.ts importing nothing). No new cycle may appear.
 */
const KNOWN_CYCLES = [['nodes/core/scene.ts', 'nodes/core/values.ts']];

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
