/**
 * Autosave wiring: every committed document change is saved (debounced) to this tab's
 * sessionStorage and to localStorage (tab-storage.ts); a full storage or a refused write is shown
 * as a message, and the status line says "Saved"/"Not saved".
 */
import { useEffect, useState } from 'react';
import { type AutosaveHold, createAutosaver, type StorageLike } from '../state/autosave.ts';
import type { EditorStore } from '../state/store.ts';
import { appAutosaveStorage } from '../state/tab-storage.ts';
import type { Message } from './Banner.tsx';

export function useAutosave(store: EditorStore, say: (m: Message) => void, hold?: AutosaveHold): string {
  const [state, setState] = useState('Saved in this browser');
  useEffect(() => {
    let storage: StorageLike;
    try {
      storage = appAutosaveStorage();
    } catch {
      setState('Not saved: browser storage is disabled');
      return;
    }
    const saver = createAutosaver(
      storage,
      (outcome) => {
        if (outcome.ok) setState('Saved in this browser');
        else if (outcome.reason === 'held') setState('Not saved: autosave paused');
        else {
          setState('Not saved');
          say({ id: 'autosave', kind: 'error', text: outcome.message });
        }
      },
      undefined,
      undefined,
      hold,
    );
    if (hold?.held) setState('Not saved: autosave paused');
    // Released (the unreadable save was downloaded or discarded): save the graph as it is now.
    const unhold = hold?.onRelease(() => {
      saver.schedule(store.getState().doc);
      saver.flush();
    });
    let last = store.getState().doc;
    const unsubscribe = store.subscribe(() => {
      const { doc, gestureBase } = store.getState();
      if (doc === last || gestureBase) return; // mid-gesture previews are saved when the gesture ends
      last = doc;
      setState('Saving…');
      saver.schedule(doc);
    });
    const flush = () => saver.flush();
    window.addEventListener('pagehide', flush);
    return () => {
      window.removeEventListener('pagehide', flush);
      unsubscribe();
      unhold?.();
      saver.flush();
      saver.dispose();
    };
  }, [store, say, hold]);
  return state;
}
