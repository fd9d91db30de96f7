/**
 * Autosave wiring: every committed document change is saved (debounced) to localStorage; a full
 * storage or a refused write is shown as a message, and the status line says "Saved"/"Not saved".
 */
import { useEffect, useState } from 'react';
import { createAutosaver } from '../state/autosave.ts';
import type { EditorStore } from '../state/store.ts';
import type { Message } from './Banner.tsx';

export function useAutosave(store: EditorStore, say: (m: Message) => void): string {
  const [state, setState] = useState('Saved in this browser');
  useEffect(() => {
    let storage: Storage;
    try {
      storage = window.localStorage;
    } catch {
      setState('Not saved: browser storage is disabled');
      return;
    }
    const saver = createAutosaver(storage, (outcome) => {
      if (outcome.ok) setState('Saved in this browser');
      else {
        setState('Not saved');
        say({ id: 'autosave', kind: 'error', text: outcome.message });
      }
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
      saver.flush();
      saver.dispose();
    };
  }, [store, say]);
  return state;
}
