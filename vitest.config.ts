import { defineConfig } from 'vitest/config';

// Unit, property and golden tests run in Node. Browser suites (tests/e2e, tests/parity) launch
// Debian Chromium themselves through playwright-core; they are ordinary Node tests too.
export default defineConfig({
  test: {
    include: ['tests/**/*.test.ts'],
    testTimeout: 30_000,
    hookTimeout: 120_000,
    pool: 'forks',
    fileParallelism: true,
    maxWorkers: 2,
  },
});
