/** Animation time: while playing, the store's `time` advances with the wall clock (one update per frame). */
import { useEffect } from 'react';
import type { EditorStore } from '../state/store.ts';

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

export function useAnimationClock(store: EditorStore, playing: boolean): void {
  useEffect(() => {
    if (!playing) return;
    const startedAt = performance.now() - store.getState().time * 1000;
    let raf = requestAnimationFrame(function tick(now) {
      store.setTime((now - startedAt) / 1000);
      raf = requestAnimationFrame(tick);
    });
    return () => cancelAnimationFrame(raf);
  }, [store, playing]);
}
