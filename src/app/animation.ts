/** Animation time: while playing, the store's `time` advances with the wall clock (one update per frame). */
import { useEffect } from 'react';
import type { EditorStore } from '../state/store.ts';

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
