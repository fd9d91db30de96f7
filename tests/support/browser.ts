/**
 * Launches Debian's Chromium through playwright-core with the flags that give WebGL2 through
 * SwiftShader on every machine (see docs/testing.md). Shared by parity, e2e and bench.
 */
import { type Browser, chromium } from 'playwright-core';

export const CHROMIUM_PATH = process.env.KLEINFLOW_CHROMIUM ?? '/usr/bin/chromium';

export const CHROMIUM_ARGS = [
  '--no-sandbox',
  '--use-angle=swiftshader',
  '--enable-unsafe-swiftshader',
  '--disable-background-networking',
  '--disable-component-update',
  '--disable-sync',
  '--no-first-run',
  '--disable-quic',
];

/** `extraArgs`: more Chromium flags (e.g. the fake camera of tests/e2e/live-sources.test.ts). */
export function launchChromium(extraArgs: readonly string[] = []): Promise<Browser> {
  return chromium.launch({
    executablePath: CHROMIUM_PATH,
    args: [...CHROMIUM_ARGS, ...extraArgs],
    headless: true,
  });
}
