/**
 * Hooks for the end-to-end suites, off unless the page URL has `?test`: `window.__kleinflow`
 * gives the store (to read and drive the document) and the live Viewport (compile and frame
 * counts, snapshots). A normal session never creates it.
 */
import type { EditorStore } from '../state/store.ts';
import { type LiveMedia, liveMedia } from '../viewport/live-media.ts';
import type { Viewport } from '../viewport/viewport.ts';

export interface TestHooks {
  store: EditorStore;
  viewport: Viewport | null;
  /** The page's camera and videos (live-media.ts). */
  live: LiveMedia;
}

declare global {
  interface Window {
    __kleinflow?: TestHooks;
  }
}

const enabled = () =>
  typeof window !== 'undefined' && new URLSearchParams(window.location.search).has('test');

/** Publishes the store and the viewport now drawing (null when it is gone), when `?test` is set. */
export function exposeForTests(store: EditorStore, viewport: Viewport | null): void {
  if (!enabled()) return;
  window.__kleinflow = { store, viewport, live: liveMedia };
}
