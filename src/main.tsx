/**
 * Entry: restores this tab's autosaved graph (or opens the default example on the first run), creates
 * the store and mounts the app. An unreadable autosave is kept and offered for download.
 */
import { StrictMode } from 'react';
import { createRoot } from 'react-dom/client';
import '@xyflow/react/dist/style.css';
import './styles/index.css';
import { emptyDocument, type GraphDoc } from '../nodes/graph/document.ts';
import { registry } from '../nodes/types/index.ts';
import { App } from './app/App.tsx';
import type { Message } from './app/Banner.tsx';
import { defaultExample } from './app/examples.ts';
import { download } from './app/files.ts';
import { appMode } from './app/present/app-mode.ts';
import { PresentApp } from './app/present/PresentApp.tsx';
import {
  AUTOSAVE_BACKUP_KEY,
  AUTOSAVE_KEY,
  type AutosaveHold,
  createAutosaveHold,
  type Restored,
  restore,
} from './state/autosave.ts';
import { createEditorStore } from './state/store.ts';
import { appAutosaveStorage } from './state/tab-storage.ts';
import { StoreContext } from './state/use-store.ts';

function start(): { doc: GraphDoc; messages: Message[]; hold: AutosaveHold; fresh: boolean } {
  let restored: Restored = { kind: 'none' };
  try {
    restored = restore(appAutosaveStorage());
  } catch {
    // storage unavailable: start fresh (the autosave hook reports it)
  }
  const fallback = defaultExample()?.doc ?? emptyDocument();
  const free = createAutosaveHold(false);
  if (restored.kind === 'ok') return { doc: restored.doc, messages: [], hold: free, fresh: false };
  if (restored.kind === 'none') return { doc: fallback, messages: [], hold: free, fresh: true };
  const { text, problems, backedUp } = restored;
  // Without a backup the broken save is the only copy: autosave waits until it is taken care of.
  const hold = createAutosaveHold(!backedUp);
  const FILE = 'kleinflow-unreadable-autosave.json';
  // After either action the banner says what is now true (autosave running again, where the copy is).
  const downloadIt = (): Message => {
    download(FILE, text, 'application/json');
    hold.release();
    return {
      id: 'restore',
      kind: 'info',
      text: backedUp
        ? `Downloaded “${FILE}” (a copy is still kept under “${AUTOSAVE_BACKUP_KEY}” in this browser).`
        : `Downloaded “${FILE}”. Autosave is on again.`,
    };
  };
  const discardIt = (): Message => {
    try {
      appAutosaveStorage().removeItem(AUTOSAVE_KEY);
    } catch {
      // storage unavailable: nothing left to discard
    }
    hold.release();
    return { id: 'restore', kind: 'info', text: 'Discarded the unreadable session. Autosave is on again.' };
  };
  // The banner says only what is true: where the text is kept, and whether autosave is paused.
  const where = backedUp
    ? `it is kept under “${AUTOSAVE_BACKUP_KEY}” in this browser`
    : 'the browser storage has no room for a backup copy, so autosave is paused until you download or discard it';
  return {
    doc: fallback,
    fresh: true,
    hold,
    messages: [
      {
        id: 'restore',
        kind: 'error',
        text: `Your last session could not be restored (${where}). Download it to repair it by hand:`,
        details: problems.map((d) => `${d.code} ${d.message}`),
        actions: backedUp
          ? [{ label: 'Download it', run: downloadIt }]
          : [
              { label: 'Download it', run: downloadIt },
              { label: 'Discard it', run: discardIt },
            ],
      },
    ],
  };
}

const { doc, messages, hold, fresh } = start();
const mode = appMode(window.location.search);
const store = createEditorStore(doc, registry);
createRoot(document.getElementById('root')!).render(
  <StrictMode>
    <StoreContext.Provider value={store}>
      {mode === 'editor' ? (
        <App initialMessages={messages} autosaveHold={hold} fitStartView={fresh} />
      ) : (
        <PresentApp mode={mode} />
      )}
    </StoreContext.Provider>
  </StrictMode>,
);
