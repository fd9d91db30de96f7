/**
 * The reader's motion preference, for every part of the app that moves something by itself (the
 * editor's pans and zooms, the view's fits); src/ui/ is the small browser-UI layer that app/,
 * editor/ and viewport/ share (docs/architecture.md).
 */

/**
 * Whether the reader asked the system for less motion. Then nothing moves unless they ask: playback
 * starts only from Play (the store starts paused and nothing else sets `playing`; the e2e
 * reduced-motion test keeps it so) and the view's own pans and zooms jump instead of gliding.
 */
export function prefersReducedMotion(): boolean {
  return typeof matchMedia === 'function' && matchMedia('(prefers-reduced-motion: reduce)').matches;
}

/** How long a movement the app makes by itself lasts: `ms`, or 0 for a reader who wants less motion. */
export const motionMs = (ms: number): number => (prefersReducedMotion() ? 0 : ms);
