/**
 * Entry: restores the autosaved graph (or opens the default example on the first run), creates
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
import { AUTOSAVE_BACKUP_KEY, type Restored, restore } from './state/autosave.ts';
import { createEditorStore } from './state/store.ts';
import { StoreContext } from './state/use-store.ts';

function start(): { doc: GraphDoc; messages: Message[] } {
  let restored: Restored = { kind: 'none' };
  try {
    restored = restore(window.localStorage);
  } catch {
    // storage unavailable: start fresh (the autosave hook reports it)
  }
  const fallback = defaultExample()?.doc ?? emptyDocument();
  if (restored.kind === 'ok') return { doc: restored.doc, messages: [] };
  if (restored.kind === 'none') return { doc: fallback, messages: [] };
  const { text, problems } = restored;
  return {
    doc: fallback,
    messages: [
      {
        id: 'restore',
        kind: 'error',
        text: `Your last session could not be restored (it is kept under “${AUTOSAVE_BACKUP_KEY}” in this browser). Download it to repair it by hand:`,
        details: problems.map((d) => `${d.code} ${d.message}`),
        actions: [
          {
            label: 'Download it',
            run: () => download('kleinflow-unreadable-autosave.json', text, 'application/json'),
          },
        ],
      },
    ],
  };
}

const { doc, messages } = start();
const mode = appMode(window.location.search);
const store = createEditorStore(doc, registry);
createRoot(document.getElementById('root')!).render(
  <StrictMode>
    <StoreContext.Provider value={store}>
      {mode === 'editor' ? <App initialMessages={messages} /> : <PresentApp mode={mode} />}
    </StoreContext.Provider>
  </StrictMode>,
);
