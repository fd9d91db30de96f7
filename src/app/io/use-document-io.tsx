/**
 * Every way into and out of the editor: open (file picker, drop anywhere, paste of a document or
 * share link, a `#g=` link at startup), Save, Copy link, PNG and GLSL export. Each open is one
 * undo step (a load-document change); a failed open leaves the graph untouched and lists every
 * problem with its path. The formats themselves live in src/io.
 */
import { type ReactNode, useCallback, useEffect, useRef, useState } from 'react';
import type { Scene } from '../../../nodes/core/scene.ts';
import type { Scene3d } from '../../../nodes/core/scene-3d.ts';
import type { GraphDoc } from '../../../nodes/graph/document.ts';
import { registry } from '../../../nodes/types/index.ts';
import { tidyIfOverlapping } from '../../editor/layout.ts';
import { isTyping } from '../../editor/typing.ts';
import type { OpenResult } from '../../io/document-io.ts';
import type { EditorStore } from '../../state/store.ts';
import type { Viewport } from '../../viewport/viewport.ts';
import { exportGlsl, exportPng, type PngExportOptions } from '../export.ts';
import { exportSvgFile } from '../export-svg.ts';
import { readDocumentFile, saveDocument } from '../files.ts';
import type { MenuItem } from '../Menu.tsx';
import { DropOverlay } from './DropOverlay.tsx';
import { ExportDialog, type Size } from './ExportDialog.tsx';
import { OpenReportPanel } from './OpenReportPanel.tsx';
import { type OpenReport, openReport } from './open-report.ts';
import { openPastedText } from './pasted-document.ts';
import { clearFragment, readStartupLink, shareLinkFor } from './share-link.ts';
import { Toast, type ToastMessage } from './Toast.tsx';
import { useAnimationExport } from './use-animation-export.tsx';
import { useMeshExport } from './use-mesh-export.tsx';

interface Options {
  readonly store: EditorStore;
  readonly scene: Scene;
  /** The picture of space when the render node is render-3d (then `scene` is empty). */
  readonly scene3d: Scene3d | null;
  /** Replaces the document as one undo step (the app also resets selection and framing). */
  load(doc: GraphDoc, label: string): void;
  viewport(): Viewport | null;
  /** While presenting the graph is read-only: a drop or a pasted graph is refused with a message. */
  readonly locked?: boolean;
}

export interface DocumentIo {
  openFile(file: File): Promise<void>;
  save(): void;
  readonly exportItems: readonly MenuItem[];
  /** Shows a short confirmation in the toast. */
  notify(text: string): void;
  /** The drop overlay, open report, toast and export dialog, to mount once in the app. */
  readonly ui: ReactNode;
}

/** What a load that replaced the user's graph says (so nobody thinks their work is gone). */
export const loadedMessage = (what: string) => `Loaded ${what} — Ctrl+Z brings your graph back.`;

/** What an edit attempted while presenting is told (the presentation never changes the graph). */
export const PRESENTING_READ_ONLY = 'Presenting: the graph is read-only. Esc goes back to the editor.';

/** Why Export → SVG refuses a 3D graph (its item is disabled then; this is the message if reached). */
export const SVG_NOT_3D =
  'No SVG: SVG export draws the circles and lines of a 2D graph; a 3D graph exports as PNG, STL or GLSL.';

/** The live render's size in css pixels (the export dialog's "view size"). */
function renderSize(): Size {
  const pane = document.querySelector<HTMLElement>('[data-testid="render-pane"]');
  return { width: pane?.clientWidth || 1280, height: pane?.clientHeight || 720 };
}

export async function copyText(text: string): Promise<boolean> {
  try {
    await navigator.clipboard.writeText(text);
    return true;
  } catch {
    // refused without a user gesture or permission: the old selection-based copy still works
    const area = Object.assign(document.createElement('textarea'), { value: text });
    document.body.append(area);
    area.select();
    const ok = document.execCommand('copy');
    area.remove();
    return ok;
  }
}

export function useDocumentIo({
  store,
  scene,
  scene3d,
  load,
  viewport,
  locked = false,
}: Options): DocumentIo {
  const [report, setReport] = useState<OpenReport | null>(null);
  const [toast, setToast] = useState<ToastMessage | null>(null);
  const [dragging, setDragging] = useState(false);
  const [exporting, setExporting] = useState(false);
  const say = useCallback(
    (kind: ToastMessage['kind'], text: string) => setToast({ id: Date.now(), kind, text }),
    [],
  );
  const dismissToast = useCallback(() => setToast(null), []);

  /** Applies an open result: loads (one undo step) or reports, never both half-way. */
  const accept = useCallback(
    (what: string, result: OpenResult) => {
      setReport(openReport(what, result));
      // Only imports get laid out: a Kleinflow document opens exactly as it was saved.
      if (result.ok)
        load(
          result.source === 'flower' ? tidyIfOverlapping(result.doc, registry) : result.doc,
          `open ${what}`,
        );
    },
    [load],
  );
  const openFile = useCallback(
    async (file: File) => accept(`“${file.name}”`, await readDocumentFile(file)),
    [accept],
  );
  const save = useCallback(() => saveDocument(store.getState().doc), [store]);

  const lockedNow = useRef(locked);
  lockedNow.current = locked;
  // A `#g=` link the page was opened with: loaded over the autosaved graph (undo returns to it).
  // A link pasted into the address bar of an open tab only changes the hash: same treatment, except
  // while presenting, which never changes the graph (the link is refused and cleared).
  useEffect(() => {
    const apply = () => {
      const link = readStartupLink(window.location.hash);
      if (link.kind === 'none') return;
      clearFragment();
      if (lockedNow.current) say('ok', PRESENTING_READ_ONLY);
      else if (link.kind === 'ok') {
        load(link.doc, 'open shared link');
        say('ok', loadedMessage('the shared graph'));
      } else
        setReport({
          kind: 'error',
          title: 'The shared link could not be opened; your graph is unchanged.',
          items: [{ path: '(link)', text: link.message, code: 'KF501' }],
        });
    };
    apply();
    window.addEventListener('hashchange', apply);
    return () => window.removeEventListener('hashchange', apply);
  }, [load, say]);

  // Drop a file anywhere; paste a whole document or share link (copied nodes stay the editor's).
  useEffect(() => {
    let depth = 0;
    const hasFiles = (e: DragEvent) => e.dataTransfer?.types.includes('Files') ?? false;
    const enter = (e: DragEvent) => {
      if (!hasFiles(e) || lockedNow.current) return;
      depth++;
      setDragging(true);
    };
    const over = (e: DragEvent) => {
      if (!hasFiles(e)) return;
      e.preventDefault();
      e.dataTransfer!.dropEffect = 'copy';
    };
    const leave = (e: DragEvent) => {
      if (!hasFiles(e)) return;
      depth = Math.max(0, depth - 1);
      if (depth === 0) setDragging(false);
    };
    const drop = (e: DragEvent) => {
      const file = e.dataTransfer?.files[0];
      depth = 0;
      setDragging(false);
      if (!file) return;
      e.preventDefault();
      e.stopPropagation(); // the graph canvas must not also treat it as its own drop
      if (lockedNow.current) say('ok', PRESENTING_READ_ONLY);
      else void openFile(file);
    };
    const paste = (e: ClipboardEvent) => {
      if (isTyping(e.target)) return;
      const result = openPastedText(e.clipboardData?.getData('text/plain') ?? '');
      if (!result) return;
      // The editor's own paste handler still sees the event (it clears its fallback timer) and
      // ignores it: the text is not its `kleinflow-clipboard` format.
      e.preventDefault();
      if (lockedNow.current) say('ok', PRESENTING_READ_ONLY);
      else accept('the pasted graph', result);
    };
    window.addEventListener('dragenter', enter);
    window.addEventListener('dragover', over);
    window.addEventListener('dragleave', leave);
    window.addEventListener('drop', drop, true);
    window.addEventListener('paste', paste, true);
    return () => {
      window.removeEventListener('dragenter', enter);
      window.removeEventListener('dragover', over);
      window.removeEventListener('dragleave', leave);
      window.removeEventListener('drop', drop, true);
      window.removeEventListener('paste', paste, true);
    };
  }, [openFile, accept, say]);

  const copyLink = useCallback(async () => {
    const link = shareLinkFor(store.getState().doc, window.location);
    if (!link.ok) return say('error', `No link: ${link.message}`);
    if (await copyText(link.url))
      say('ok', `Link copied (${link.url.length} characters): anyone who opens it gets this graph.`);
    else say('error', 'The browser refused to copy the link to the clipboard.');
  }, [store, say]);

  const currentScene = useRef(scene);
  currentScene.current = scene;
  const currentScene3d = useRef(scene3d);
  currentScene3d.current = scene3d;
  const glsl = (flavour: 'webgl2' | 'shadertoy') =>
    say('ok', exportGlsl(store.getState().doc, currentScene3d.current ?? currentScene.current, flavour));
  const animation = useAnimationExport({
    store,
    samples: scene.samples,
    viewport,
    viewSize: renderSize,
    say,
  });
  const mesh = useMeshExport({ store, say });
  const svg = () => {
    if (currentScene3d.current) return say('error', SVG_NOT_3D);
    const { doc } = store.getState();
    const r = exportSvgFile(doc, currentScene.current, doc.view, renderSize());
    say(r.ok ? 'ok' : 'error', r.message);
  };
  const exportItems: MenuItem[] = [
    { label: 'PNG image…', hint: 'any size, graph inside', onSelect: () => setExporting(true) },
    animation.item,
    scene3d
      ? { label: 'SVG (circles and lines)', hint: 'only for 2D graphs', disabled: true, onSelect: svg }
      : { label: 'SVG (circles and lines)', hint: 'vector, mirrors only', onSelect: svg },
    mesh.item,
    { label: 'Copy share link', hint: 'graph in the URL', onSelect: () => void copyLink() },
    { label: 'GLSL shader (.frag)', hint: 'WebGL2, values baked', onSelect: () => glsl('webgl2') },
    { label: 'Shadertoy (.shadertoy.glsl)', hint: 'paste into Shadertoy', onSelect: () => glsl('shadertoy') },
  ];

  const runExport = async (o: PngExportOptions, onProgress: (f: number) => boolean) => {
    const v = viewport();
    if (!v) throw new Error('the WebGL2 renderer is not running');
    const done = await exportPng(v, store.getState().doc, currentScene.current, o, onProgress);
    if (done) say('ok', `Exported ${o.width} × ${o.height} PNG (the graph is inside it).`);
    return done;
  };

  const ui = (
    <>
      {dragging && <DropOverlay />}
      {report && <OpenReportPanel report={report} onDismiss={() => setReport(null)} />}
      {toast && <Toast key={toast.id} toast={toast} onDone={dismissToast} />}
      {exporting && (
        <ExportDialog
          viewSize={renderSize()}
          view={store.getState().doc.view}
          defaultSamples={Math.max(scene.samples, 16)}
          edgeWidth={scene.tile.edgeWidth}
          run={runExport}
          onClose={() => setExporting(false)}
        />
      )}
      {animation.ui}
      {mesh.ui}
    </>
  );
  const notify = useCallback((text: string) => say('ok', text), [say]);
  return { openFile, save, exportItems, notify, ui };
}
