/**
 * Keyboard of the graph editor: palette (Space, Ctrl K), clipboard (Ctrl C/X/V), duplicate
 * (Ctrl D), select all (Ctrl A), the inspector (I), mute (M), group / ungroup (Ctrl G, Ctrl Shift G)
 * and opening a group (Enter). Undo/redo live in the app shell.
 */
import type { Edge, ReactFlowInstance } from '@xyflow/react';
import { type RefObject, useEffect } from 'react';
import { registry } from '../../nodes/types/index.ts';
import { type ClipboardData, copyNodes, preparePaste } from '../state/clipboard.ts';
import type { EditorStore } from '../state/store.ts';
import { lastCopied, putOnEvent, readClipboard, readEvent, writeClipboard } from './clipboard-io.ts';
import type { KfNode } from './flow-model.ts';
import { clearShift, sizer } from './layout.ts';
import { groupSelection, ungroupSelection } from './tools/group-actions.ts';
import { muteToggle } from './tools/mute.ts';
import { isTyping } from './typing.ts';

type Point = { x: number; y: number };

interface Options {
  readonly store: EditorStore;
  readonly flow: ReactFlowInstance<KfNode, Edge>;
  /** Last pointer position over the graph (css px), null when outside. */
  readonly pointer: RefObject<Point | null>;
  readonly paletteOpen: boolean;
  /** Opens the search palette at `at` (screen px), or at its usual place when there is no pointer. */
  openPalette(at: Point | null): void;
  toggleInspector(): void;
  openGroup(nodeId: string): void;
}

/**
 * Pastes clipboard nodes (new ids) with their top-left at `where` (graph coordinates), or further
 * right where they would cover a node, selecting them.
 */
export function pasteNodes(store: EditorStore, data: ClipboardData, where?: Point): void {
  const at = where ? ([where.x, where.y] as const) : undefined;
  const { doc } = store.getState();
  const pasted = preparePaste(doc, data, at);
  const dx = clearShift(doc, pasted.nodes, sizer(doc, registry));
  const nodes = pasted.nodes.map((n) => ({
    ...n,
    position: [n.position[0] + dx, n.position[1]] as [number, number],
  }));
  const { edges } = pasted;
  store.dispatch({ type: 'paste', nodes, edges }, 'paste');
  store.setSelection(nodes.map((n) => n.id));
}

/** How long Ctrl V waits for the browser's paste event before reading the clipboard itself. */
const PASTE_EVENT_WAIT_MS = 120;

/** Text selected on the page (then Ctrl C copies that text, not nodes). */
const hasTextSelection = () => (window.getSelection()?.toString() ?? '') !== '';

export function useGraphKeys(o: Options): void {
  const { store, flow, pointer, paletteOpen, openPalette, toggleInspector, openGroup } = o;
  useEffect(() => {
    const selected = () => copyNodes(store.getState().doc, store.getState().selection);
    /** Graph position under the pointer (paste target), or undefined to paste beside the originals. */
    const here = () => (pointer.current ? flow.screenToFlowPosition(pointer.current) : undefined);
    let pasteFallback: ReturnType<typeof setTimeout> | undefined;
    const onKey = (e: KeyboardEvent) => {
      if (isTyping(e.target) || paletteOpen) return;
      const mod = e.ctrlKey || e.metaKey;
      const key = e.key.toLowerCase();
      if ((key === ' ' && !mod) || (mod && key === 'k')) {
        openPalette(pointer.current);
      } else if (mod && (key === 'c' || key === 'x') && !hasTextSelection()) {
        // No preventDefault: the browser's copy/cut event follows and carries the JSON too.
        const data = selected();
        if (!data) return;
        void writeClipboard(data);
        if (key === 'x') store.dispatch({ type: 'remove', nodeIds: data.nodes.map((n) => n.id) }, 'cut');
        return;
      } else if (mod && key === 'v') {
        // The paste event normally follows; if the browser sends none, read the clipboard ourselves.
        clearTimeout(pasteFallback);
        pasteFallback = setTimeout(() => {
          const at = here();
          void readClipboard().then((data) => data && pasteNodes(store, data, at));
        }, PASTE_EVENT_WAIT_MS);
        return;
      } else if (mod && key === 'd') {
        const data = selected();
        if (data) pasteNodes(store, data);
      } else if (mod && key === 'a') {
        store.setSelection(store.getState().doc.nodes.map((n) => n.id));
      } else if (!mod && !e.altKey && key === 'i') {
        toggleInspector();
      } else if (mod && key === 'g') {
        const { doc, selection } = store.getState();
        const change = e.shiftKey ? ungroupSelection(doc, selection) : groupSelection(doc, selection);
        if (change) store.dispatch(change, e.shiftKey ? 'ungroup' : 'group');
        if (change?.type === 'group') store.setSelection([change.groupId]);
      } else if (!mod && key === 'enter') {
        const { doc, selection } = store.getState();
        const only = selection.size === 1 ? doc.nodes.find((n) => selection.has(n.id)) : undefined;
        if (!only?.group) return;
        openGroup(only.id);
      } else if (!mod && !e.altKey && key === 'm') {
        const { doc, selection } = store.getState();
        const change = muteToggle(doc, selection);
        if (!change) return;
        store.dispatch(change, change.type === 'set-muted' && change.muted ? 'mute' : 'unmute');
      } else return;
      e.preventDefault();
    };
    const onCopy = (e: ClipboardEvent) => {
      if (isTyping(e.target) || hasTextSelection()) return;
      // On cut the nodes are already gone (keydown removed them): put what keydown copied.
      const data = e.type === 'cut' ? lastCopied() : selected();
      if (data && putOnEvent(e, data)) e.preventDefault();
    };
    const onPaste = (e: ClipboardEvent) => {
      if (isTyping(e.target) || paletteOpen) return;
      clearTimeout(pasteFallback);
      const data = readEvent(e);
      if (!data) return;
      e.preventDefault();
      pasteNodes(store, data, here());
    };
    window.addEventListener('keydown', onKey);
    document.addEventListener('copy', onCopy);
    document.addEventListener('cut', onCopy);
    document.addEventListener('paste', onPaste);
    return () => {
      clearTimeout(pasteFallback);
      window.removeEventListener('keydown', onKey);
      document.removeEventListener('copy', onCopy);
      document.removeEventListener('cut', onCopy);
      document.removeEventListener('paste', onPaste);
    };
  }, [store, flow, pointer, paletteOpen, openPalette, toggleInspector, openGroup]);
}
