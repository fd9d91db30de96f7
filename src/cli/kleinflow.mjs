#!/usr/bin/env node
// The `kleinflow` executable (package.json "bin"): registers tsx so the TypeScript sources run
// as they are, right after `npm install`, then hands over to main.ts.
import { register } from 'tsx/esm/api';

register();
try {
  const { main } = await import('./main.ts');
  const { nodeIo } = await import('./node-io.ts');
  process.exitCode = await main(process.argv.slice(2), nodeIo());
} catch (e) {
  // Only reached when the sources themselves fail to load: main() catches everything else.
  process.stderr.write(`kleinflow: internal error: ${e instanceof Error ? e.message : String(e)}\n`);
  process.exitCode = 70;
}
