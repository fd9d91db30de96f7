/**
 * Bundles a TS/TSX entry (and everything it imports, React included) into one browser script with
 * esbuild, for `page.addScriptTag({ content })` on a blank page. Browser suites and the GPU
 * benchmark share it. Bundles are cached per entry for the life of the process.
 */
import { build } from 'esbuild';

const cache = new Map<string, Promise<string>>();

export function bundle(entry: string): Promise<string> {
  let text = cache.get(entry);
  if (!text) {
    text = build({
      entryPoints: [entry],
      bundle: true,
      write: false,
      format: 'iife',
      platform: 'browser',
      target: 'es2022',
      jsx: 'automatic',
      // Development build: React's checks on, and the runtime's strict checks (e.g. never upload NaN).
      define: { 'process.env.NODE_ENV': '"development"' },
      sourcemap: 'inline',
      logLevel: 'silent',
    }).then((r) => r.outputFiles[0].text);
    cache.set(entry, text);
  }
  return text;
}
