/**
 * The app shell: top bar, graph editor | live render (resizable; tabs on a phone), status line,
 * or the presentation in their place. Owns the evaluation (memoised per document change), global
 * shortcuts, files and export.
 */
import { ReactFlowProvider } from '@xyflow/react';
import { useCallback, useEffect, useMemo, useRef, useState } from 'react';
import type { Diagnostic } from '../../nodes/core/diagnostics.ts';
import { emptyDocument, type GraphDoc, type GraphNode } from '../../nodes/graph/document.ts';
import type { NodePath } from '../../nodes/graph/flatten.ts';
import { registry } from '../../nodes/types/index.ts';
import { fixPatches } from '../editor/diagnostic-fix.ts';
import { GraphEditor } from '../editor/GraphEditor.tsx';
import { InspectorExtrasContext } from '../editor/inspector-extras.ts';
import { scopeDiagnostics } from '../editor/tools/scope-evaluation.ts';
import { isTyping } from '../editor/typing.ts';
import { sharePayload } from '../io/share-url.ts';
import type { AutosaveHold } from '../state/autosave.ts';
import { createEvaluator } from '../state/evaluation.ts';
import { useEditorState, useStore } from '../state/use-store.ts';
import { fitSquareView, openingView, pictureBounds } from '../viewport/fit-view.ts';
import type { Viewport } from '../viewport/viewport.ts';
import { useAnimationClock } from './animation.ts';
import { Banner, type Message } from './Banner.tsx';
import { EXAMPLES } from './examples.ts';
import { ExamplesGallery } from './gallery/ExamplesGallery.tsx';
import { HelpDialog } from './help/HelpDialog.tsx';
import { loadedMessage, PRESENTING_READ_ONLY, useDocumentIo } from './io/use-document-io.tsx';
import { LiveSourceSection } from './LiveSourceSection.tsx';
import { nodeTitle } from './node-title.ts';
import { PictureFileSection } from './PictureFileSection.tsx';
import { Presentation } from './present/Presentation.tsx';
import { type RenderInfo, RenderPane } from './RenderPane.tsx';
import { RecentPanel } from './recent/RecentDialog.tsx';
import { pictureDone, useRecent } from './recent/use-recent.ts';
import { SplitPane } from './SplitPane.tsx';
import { StatusBar } from './StatusBar.tsx';
import { TopBar } from './TopBar.tsx';
import { useAutosave } from './use-autosave.ts';
import { WalkthroughPanel } from './walkthrough/WalkthroughPanel.tsx';
import { WelcomeCard } from './welcome/WelcomeCard.tsx';
import { rememberWelcome, welcomeSeen } from './welcome/welcome-memory.ts';

/** The live render pane's size in CSS pixels (0 × 0 before it is laid out). */
const renderPaneSize = () => {
  const pane = document.querySelector<HTMLElement>('[data-testid="render-pane"]');
  return { width: pane?.clientWidth ?? 0, height: pane?.clientHeight ?? 0 };
};

const storage = (): Storage | undefined => {
  try {
    return window.localStorage;
  } catch {
    return undefined;
  }
};

interface Props {
  readonly initialMessages: readonly Message[];
  /** Held while an unreadable autosave without a backup must not be overwritten (see main.tsx). */
  readonly autosaveHold?: AutosaveHold;
  /** The start-up example (no autosave yet): framed to the pane once it is laid out, as Examples does. */
  readonly fitStartView?: boolean;
}

const imageSections = (node: GraphNode) => (
  <>
    <PictureFileSection node={node} />
    <LiveSourceSection node={node} />
  </>
);

export function App({ initialMessages, autosaveHold, fitStartView = false }: Props) {
  const store = useStore();
  const doc = useEditorState((s) => s.doc);
  const time = useEditorState((s) => s.time);
  const playing = useEditorState((s) => s.playing);
  const history = useEditorState((s) => s.history);
  const evaluate = useMemo(() => createEvaluator(registry), []);
  const evaluation = useMemo(() => evaluate(doc, time), [evaluate, doc, time]);
  // The hovered node by its document path, so a group hovered in the graph lights up all it draws.
  const [hovered, setHovered] = useState<NodePath | null>(null);
  const [renderDiagnostics, setRenderDiagnostics] = useState<Diagnostic[]>([]);
  const [renderInfo, setRenderInfo] = useState<RenderInfo | null>(null);
  const [messages, setMessages] = useState<readonly Message[]>(initialMessages);
  const [help, setHelp] = useState(false);
  // A link that brings a document (#g=…) shows that document, not the first-visit card over it.
  const [welcome, setWelcome] = useState(
    () => !welcomeSeen(storage()) && sharePayload(window.location.hash) === null,
  );
  const [walkthrough, setWalkthrough] = useState(false);
  const [gallery, setGallery] = useState(false);
  const [presenting, setPresenting] = useState(false);
  const [inspecting, setInspecting] = useState(false);
  const stopInspecting = useCallback(() => setInspecting(false), []);
  const [frameKey, setFrameKey] = useState(0);
  const viewport = useRef<Viewport | null>(null);
  const fileInput = useRef<HTMLInputElement>(null);
  useAnimationClock(store, playing);
  const say = useCallback((m: Message) => setMessages((ms) => [...ms.filter((x) => x.id !== m.id), m]), []);
  const saveState = useAutosave(store, say, autosaveHold);
  const getViewport = useCallback(() => viewport.current, []);
  const recent = useRecent(store, getViewport, say, pictureDone(renderInfo));
  const { switchTo } = recent;

  const load = useCallback(
    (next: GraphDoc, label: string, recentId?: string) => {
      // Another document: saved as its own Recent entry, never over the one it replaces.
      switchTo(recentId);
      store.dispatch({ type: 'load-document', doc: next }, label);
      store.setSelection([]);
      setRenderDiagnostics([]);
      setFrameKey((k) => k + 1);
    },
    [store, switchTo],
  );

  const io = useDocumentIo({
    store,
    scene: evaluation.scene,
    scene3d: evaluation.scene3d,
    load,
    viewport: getViewport,
    locked: presenting,
  });
  const { save, exportItems } = io;
  const { notify } = io;
  const dismissWelcome = useCallback(() => {
    rememberWelcome(storage());
    setWelcome(false);
  }, []);
  useEffect(() => {
    if (!fitStartView) return;
    // After layout, so the pane has its size; silent: framing is not an edit to undo.
    const frame = requestAnimationFrame(() => {
      const { view } = store.getState().doc;
      const { center, scale } = fitSquareView(view, renderPaneSize());
      if (scale !== view.scale)
        store.dispatchSilently({ type: 'set-view', view: { center: [center[0], center[1]], scale } });
    });
    return () => cancelAnimationFrame(frame);
  }, [fitStartView, store]);
  const openExample = useCallback(
    (ex: (typeof EXAMPLES)[number]) => {
      const replacing = store.getState().doc.nodes.length > 0;
      // Examples are framed for a square pane: in a tall one, zoom out so none of it is cropped, and
      // never open cropped where Fit would frame more (openingView). One undo step with the load,
      // so Ctrl+Z restores the previous graph and its view together.
      const shown = evaluate(ex.doc, 0);
      const bounds = shown.scene3d ? null : pictureBounds(shown.scene);
      const { center, scale } = openingView(ex.doc.view, bounds, renderPaneSize());
      load({ ...ex.doc, view: { center: [center[0], center[1]], scale } }, `open ${ex.title}`);
      if (replacing) notify(loadedMessage(`“${ex.title}”`));
      setHelp(false);
      setGallery(false);
      dismissWelcome();
    },
    [store, load, notify, dismissWelcome, evaluate],
  );
  const startWalkthrough = useCallback(() => {
    if (store.getState().doc.nodes.length > 0) load(emptyDocument('My *333 kaleidoscope'), 'new document');
    setHelp(false);
    setWalkthrough(true);
    dismissWelcome();
  }, [store, load, dismissWelcome]);

  const open = useCallback(() => fileInput.current?.click(), []);

  useEffect(() => {
    const onKey = (e: KeyboardEvent) => {
      if (isTyping(e.target)) return;
      const mod = e.ctrlKey || e.metaKey;
      const key = e.key.toLowerCase();
      const edits = mod && ['z', 'y', 'o', 'x', 'v', 'd', 'a'].includes(key);
      if (presenting && (edits || e.key === 'Delete' || e.key === 'Backspace')) notify(PRESENTING_READ_ONLY);
      else if (mod && key === 'z' && !e.shiftKey) store.undo();
      else if (mod && (key === 'y' || (key === 'z' && e.shiftKey))) store.redo();
      else if (mod && key === 's') save();
      else if (mod && key === 'o') open();
      else if (!mod && e.key === '?' && !presenting) setHelp(true);
      else return;
      e.preventDefault();
    };
    window.addEventListener('keydown', onKey);
    return () => window.removeEventListener('keydown', onKey);
  }, [store, save, open, presenting, notify]);

  const onViewport = useCallback((v: Viewport | null) => {
    viewport.current = v;
  }, []);
  // The status list is the top level's: a problem inside a group names the group and the node in it.
  const allDiagnostics = useMemo(
    () => scopeDiagnostics([...evaluation.diagnostics, ...renderDiagnostics], evaluation, [], doc),
    [evaluation, doc, renderDiagnostics],
  );

  const graphEditor = (inspectorTab: boolean) => (
    <InspectorExtrasContext.Provider value={imageSections}>
      <ReactFlowProvider>
        <GraphEditor
          evaluation={evaluation}
          extraDiagnostics={renderDiagnostics}
          hovered={hovered}
          frameKey={frameKey}
          onHover={setHovered}
          inspectorTab={inspectorTab}
        />
      </ReactFlowProvider>
    </InspectorExtrasContext.Provider>
  );

  if (presenting)
    return (
      <>
        <Presentation onExit={() => setPresenting(false)} />
        {io.ui}
      </>
    );
  return (
    <div className="kf-app">
      <TopBar
        title={doc.meta.title ?? ''}
        undoLabel={history.past.at(-1)?.label ?? null}
        redoLabel={history.future[0]?.label ?? null}
        playing={playing}
        exportItems={exportItems}
        onTitle={(title) =>
          store.dispatch({ type: 'set-meta', meta: { ...doc.meta, title } }, 'rename document')
        }
        onExamples={() => setGallery(true)}
        onNew={() => load(emptyDocument(), 'new document')}
        onOpen={open}
        onRecent={() => recent.setOpen(true)}
        onSave={save}
        onUndo={store.undo}
        onRedo={store.redo}
        onPlay={() => store.setPlaying(!playing)}
        onHelp={() => setHelp(true)}
        onPresent={() => setPresenting(true)}
        inspecting={inspecting}
        onInspect={() => setInspecting(!inspecting)}
      />
      <Banner
        messages={messages}
        onDismiss={(id) => setMessages((ms) => ms.filter((m) => m.id !== id))}
        onReplace={(id, next) => setMessages((ms) => ms.map((m) => (m.id === id ? next : m)))}
      />
      <SplitPane
        left={graphEditor(false)}
        inspector={graphEditor(true)}
        right={
          <RenderPane
            evaluation={evaluation}
            hovered={hovered}
            onHover={setHovered}
            onDiagnostics={setRenderDiagnostics}
            onFrame={setRenderInfo}
            onViewport={onViewport}
            inspecting={inspecting}
            onInspectingOff={stopInspecting}
          />
        }
      />
      <StatusBar
        diagnostics={allDiagnostics}
        render={renderInfo}
        nodes={doc.nodes.length}
        edges={doc.edges.length}
        saveState={saveState}
        titleOf={(id) => nodeTitle(doc, id, registry)}
        onSelectNode={(id) => store.setSelection([id])}
        onFix={(fix) =>
          store.dispatch({ type: 'set-params', patches: fixPatches(evaluation, fix) }, fix.label)
        }
      />
      <input
        ref={fileInput}
        type="file"
        accept=".json,.kleinflow.json,application/json,image/png"
        hidden
        data-testid="open-file"
        onChange={(e) => {
          const file = e.target.files?.[0];
          e.target.value = '';
          if (file) void io.openFile(file);
        }}
      />
      {help && (
        <HelpDialog
          examples={EXAMPLES}
          onExample={openExample}
          onWalkthrough={startWalkthrough}
          onClose={() => setHelp(false)}
        />
      )}
      {gallery && (
        <ExamplesGallery examples={EXAMPLES} onOpen={openExample} onClose={() => setGallery(false)} />
      )}
      {welcome && (
        <WelcomeCard
          examples={EXAMPLES}
          onExample={openExample}
          onWalkthrough={startWalkthrough}
          onEmpty={() => {
            load(emptyDocument(), 'new document');
            dismissWelcome();
          }}
          onDismiss={dismissWelcome}
        />
      )}
      {recent.open && <RecentPanel recent={recent} load={load} notify={notify} />}
      {walkthrough && (
        <WalkthroughPanel doc={doc} evaluation={evaluation} onClose={() => setWalkthrough(false)} />
      )}
      {io.ui}
    </div>
  );
}
