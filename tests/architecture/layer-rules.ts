/**
 * The import rules of docs/architecture.md "Layers", as a checker over (path, source) pairs so that
 * the test can run it both on the project and on made-up offending files:
 *
 *   nodes/       no shader-gen/, no src/; no UI package, no Node built-in, no DOM or WebGL
 *   shader-gen/  nodes/ only; no src/; no UI package, no Node built-in, no DOM or WebGL
 *   src/         the app, folder by folder (SRC_RULES): which sibling folders each may import,
 *                and whether it must run without a browser (cli/, io/: they serve the CLI in Node)
 *
 * Every relative import must land in the project's code folders (src, nodes, shader-gen, examples).
 */
import { posix, resolve } from 'node:path';

export interface SourceFile {
  /** Repository-relative path with '/' separators, e.g. 'src/app/App.tsx'. */
  readonly path: string;
  readonly source: string;
}

export interface Violation {
  readonly file: string;
  readonly what: string;
  readonly rule: string;
}

/**
 * Removes comments and the contents of '…' / "…" strings (keeping template literals, whose text is
 * generated GLSL), so that words in comments and import paths are not mistaken for code.
 */
export function stripCommentsAndStrings(src: string): string {
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
export function importsOf(src: string): string[] {
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

/**
 * Where a relative import lands: its first one or two path segments ('nodes', 'src/app'), or ''
 * for a package. Paths are resolved with '/' separators whatever the platform.
 */
export function landing(file: string, spec: string): string {
  if (!spec.startsWith('.')) return '';
  const target = posix.normalize(posix.join(posix.dirname(file), spec));
  const parts = target.split('/');
  return parts[0] === 'src' && parts.length > 2 ? `src/${parts[1]}` : parts[0];
}

export const UI_PACKAGES = /^(react|react-dom|@xyflow\/[^/]+|playwright|playwright-core|jsdom)(\/|$)/;
const NODE_BUILTINS = /^node:|^(fs|path|child_process|os|url|worker_threads)(\/|$)/;
/** Browser-only globals: the DOM, the window, the canvas and WebGL. */
export const DOM_GLOBALS =
  /(?<![\w$.])(document|window|localStorage|navigator)\s*\.|\b(WebGL2?RenderingContext|HTMLCanvasElement|requestAnimationFrame)\b|\.getContext\s*\(/;

/**
 * The src/ folders and what each may import besides nodes/ and shader-gen/ (and itself). `node`:
 * it also runs in Node (the CLI), so no UI package and no browser global.
 */
export const SRC_RULES: Readonly<Record<string, { siblings: readonly string[]; node?: true }>> = {
  'src/app': { siblings: ['src/editor', 'src/viewport', 'src/state', 'src/io', 'src/ui'] },
  'src/editor': { siblings: ['src/state', 'src/ui'] },
  'src/viewport': { siblings: ['src/ui'] },
  'src/ui': { siblings: [] },
  'src/state': { siblings: [] },
  'src/io': { siblings: [], node: true },
  'src/cli': { siblings: ['src/io'], node: true },
  'src/styles': { siblings: [] },
};
/** Files directly in src/ (the entry point) may import anything in the app. */
const SRC_ENTRY_SIBLINGS = Object.keys(SRC_RULES);

const CODE_FOLDERS = ['src', 'nodes', 'shader-gen', 'examples'];

/** Every rule broken by one file. */
export function checkFile(file: SourceFile): Violation[] {
  const bad: Violation[] = [];
  const { path } = file;
  const top = path.split('/')[0];
  const pure = top === 'nodes' || top === 'shader-gen';
  const folder = landing(path, './x');
  const srcRule = top === 'src' ? SRC_RULES[folder] : undefined;
  const add = (what: string, rule: string) => bad.push({ file: path, what, rule });
  if (top === 'src' && folder !== 'src' && !srcRule) add(folder, 'a src/ folder with no rule in SRC_RULES');
  const nodeOnly = pure || srcRule?.node === true;

  for (const spec of importsOf(stripImportsOnly(file.source))) {
    const to = landing(path, spec);
    if (to !== '' && !CODE_FOLDERS.includes(to.split('/')[0]))
      add(spec, 'a relative import leaves the code folders');
    if (top === 'nodes' && (to === 'shader-gen' || to.startsWith('src')))
      add(spec, 'nodes/ imports only nodes/');
    if (top === 'shader-gen' && to.startsWith('src')) add(spec, 'shader-gen/ never imports src/');
    if (pure && NODE_BUILTINS.test(spec)) add(spec, `${top}/ runs in the browser too: no Node built-ins`);
    if (nodeOnly && UI_PACKAGES.test(spec)) add(spec, `${pure ? top : folder}/ has no UI packages`);
    if (top === 'src' && to.startsWith('src/') && to !== folder) {
      const allowed = srcRule ? srcRule.siblings : SRC_ENTRY_SIBLINGS;
      if (!allowed.includes(to)) add(spec, `${folder}/ may not import ${to}/`);
    }
  }
  if (nodeOnly) {
    const m = stripCommentsAndStrings(file.source).match(DOM_GLOBALS);
    if (m) add(m[0], `${pure ? top : folder}/ uses no DOM or WebGL`);
  }
  return bad;
}

/**
 * The source with comments removed but strings kept (import specifiers are strings), so that an
 * import quoted in a comment is not counted.
 */
function stripImportsOnly(src: string): string {
  return src.replace(/\/\*[\s\S]*?\*\//g, ' ').replace(/(^|[^:'"`\\])\/\/[^\n]*/g, '$1');
}

/** Every violation in a set of files. */
export const checkFiles = (files: readonly SourceFile[]): Violation[] => files.flatMap(checkFile);

/** Repository-relative '/'-separated path of an absolute file under root. */
export const repoPath = (root: string, file: string): string =>
  resolve(file)
    .slice(resolve(root).length + 1)
    .split(/[\\/]/)
    .join('/');
