/**
 * Saves this tab's document to the Recent list (IndexedDB) a little while after each change, with
 * a thumbnail of the render. Each tab saves under its own entry id (tab-storage.ts), and a new
 * document in the tab (New, Open, an example, a share link) starts a new entry, so nothing saved
 * before is overwritten. If IndexedDB is missing, refused or full the work is still autosaved
 * (localStorage and the tab's sessionStorage): the person is told once, and saving goes on trying.
 */
import { useCallback, useEffect, useMemo, useRef, useState } from 'react';
import { idbRecentStore, type RecentStore } from '../../state/recent-docs.ts';
import type { EditorStore } from '../../state/store.ts';
import { newRecentId, tabRecentId } from '../../state/tab-storage.ts';
import type { Viewport } from '../../viewport/viewport.ts';
import type { Message } from '../Banner.tsx';
import type { RenderInfo } from '../RenderPane.tsx';
import { renderThumbnail } from './thumbnail.ts';

/** Longer than the autosave's delay: the picture has had time to draw before its thumbnail is taken. */
export const RECENT_DELAY_MS = 1500;
/** Whether the render pane's picture has all its samples (then its thumbnail is worth taking). */
export const pictureDone = (info: RenderInfo | null) => info !== null && info.samples >= info.target;

export interface Recent {
  readonly store: RecentStore;
  /** The Recent dialog is shown. */
  readonly open: boolean;
  setOpen(open: boolean): void;
  /** The entry this tab saves to. */
  currentId(): string;
  /** The tab now holds another document: `id` when it is a Recent entry reopened, else a new one. */
  switchTo(id?: string): void;
}

export const RECENT_UNAVAILABLE =
  'Recent documents cannot be kept in this browser (its database is unavailable or full). Your work is still autosaved in this tab; Save keeps a file.';

export function useRecent(
  store: EditorStore,
  viewport: () => Viewport | null,
  say: (m: Message) => void,
  /** The picture has all its samples (RenderPane's frame info). */
  pictureDone: boolean,
): Recent {
  const backend = useMemo(() => idbRecentStore(), []);
  const tabId = useMemo(() => tabRecentId(), []);
  const warned = useRef(false);
  const [open, setOpen] = useState(false);
  /** Writes a pending save now; writes the entry again (set by the effect). */
  const flushRef = useRef(() => {});
  const writeRef = useRef(() => {});
  /** The last write had no picture yet (a new shader can take seconds to compile). */
  const needsThumbnail = useRef(false);

  useEffect(() => {
    let timer: ReturnType<typeof setTimeout> | undefined;
    const write = () => {
      timer = undefined;
      const { doc, history } = store.getState();
      // A document nobody has touched (the start-up example framed to the pane) is no one's work.
      if (history.past.length === 0) return;
      // Only a graph with a render node has a picture (else the pane shows an empty canvas).
      const drawn = doc.nodes.some((n) => n.type === 'render' || n.type === 'render-3d');
      const thumbnail = drawn ? renderThumbnail(viewport()) : undefined;
      needsThumbnail.current = drawn && !thumbnail;
      const entry = {
        id: tabId.get(),
        title: doc.meta.title?.trim() || 'Untitled',
        savedAt: Date.now(),
        thumbnail,
        text: JSON.stringify(doc),
      };
      backend.put(entry).catch((e: unknown) => {
        if (warned.current) return;
        warned.current = true;
        console.warn('Recent documents unavailable:', e);
        say({ id: 'recent', kind: 'warning', text: RECENT_UNAVAILABLE });
      });
    };
    writeRef.current = write;
    let last = store.getState().doc;
    const unsubscribe = store.subscribe(() => {
      const { doc, gestureBase } = store.getState();
      if (doc === last || gestureBase) return;
      last = doc;
      clearTimeout(timer);
      needsThumbnail.current = false;
      timer = setTimeout(write, RECENT_DELAY_MS);
    });
    // Leaving the page: write what is pending now (IndexedDB may still finish it after pagehide).
    const flush = () => {
      if (timer === undefined) return;
      clearTimeout(timer);
      write();
    };
    flushRef.current = flush;
    window.addEventListener('pagehide', flush);
    return () => {
      window.removeEventListener('pagehide', flush);
      unsubscribe();
      flush();
    };
  }, [store, backend, tabId, viewport, say]);

  // The picture finished after an entry was written without one: write it again, now with it.
  useEffect(() => {
    if (pictureDone && needsThumbnail.current) writeRef.current();
  }, [pictureDone]);

  const switchTo = useCallback(
    (id?: string) => {
      // The last edits of the document being replaced go to its own entry first.
      flushRef.current();
      tabId.set(id ?? newRecentId());
    },
    [tabId],
  );
  return useMemo(
    () => ({ store: backend, open, setOpen, currentId: tabId.get, switchTo }),
    [backend, open, tabId, switchTo],
  );
}
