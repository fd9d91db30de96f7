/**
 * Keyboard of the graph editor: palette (Space, Ctrl K), clipboard (Ctrl C/X/V), duplicate
 * (Ctrl D), select all (Ctrl A) and the inspector (I). Undo/redo live in the app shell.
 */
import type { Edge, ReactFlowInstance } from '@xyflow/react';
import { type RefObject, useEffect } from 'react';
import { type ClipboardData, copyNodes, preparePaste } from '../state/clipboard.ts';
import type { EditorStore } from '../state/store.ts';
import { readClipboard, writeClipboard } from './clipboard-io.ts';
import type { KfNode } from './flow-model.ts';
import { isTyping } from './typing.ts';

type Point = { x: number; y: number };

interface Options {
  readonly store: EditorStore;
  readonly flow: ReactFlowInstance<KfNode, Edge>;
  /** Last pointer position over the graph (css px), null when outside. */
  readonly pointer: RefObject<Point | null>;
  readonly wrapper: RefObject<HTMLDivElement | null>;
  readonly paletteOpen: boolean;
  openPalette(at: Point): void;
  toggleInspector(): void;
}

/** Pastes clipboard nodes (new ids) with their top-left at `where` (graph coordinates), selecting them. */
export function pasteNodes(store: EditorStore, data: ClipboardData, where?: Point): void {
  const at = where ? ([where.x, where.y] as const) : undefined;
  const { nodes, edges } = preparePaste(store.getState().doc, data, at);
  store.dispatch({ type: 'paste', nodes, edges }, 'paste');
  store.setSelection(nodes.map((n) => n.id));
}

export function useGraphKeys(o: Options): void {
  const { store, flow, pointer, wrapper, paletteOpen, openPalette, toggleInspector } = o;
  useEffect(() => {
    const selected = () => copyNodes(store.getState().doc, store.getState().selection);
    const onKey = (e: KeyboardEvent) => {
      if (isTyping(e.target) || paletteOpen) return;
      const mod = e.ctrlKey || e.metaKey;
      const key = e.key.toLowerCase();
      if ((key === ' ' && !mod) || (mod && key === 'k')) {
        const rect = wrapper.current!.getBoundingClientRect();
        openPalette(pointer.current ?? { x: rect.left + rect.width / 2, y: rect.top + rect.height / 3 });
      } else if (mod && (key === 'c' || key === 'x')) {
        const data = selected();
        if (!data) return; // nothing selected: leave the browser's own copy alone
        void writeClipboard(data);
        if (key === 'x') store.dispatch({ type: 'remove', nodeIds: data.nodes.map((n) => n.id) }, 'cut');
      } else if (mod && key === 'v') {
        const at = pointer.current ? flow.screenToFlowPosition(pointer.current) : undefined;
        void readClipboard().then((data) => data && pasteNodes(store, data, at));
      } else if (mod && key === 'd') {
        const data = selected();
        if (data) pasteNodes(store, data);
      } else if (mod && key === 'a') {
        store.setSelection(store.getState().doc.nodes.map((n) => n.id));
      } else if (!mod && !e.altKey && key === 'i') {
        toggleInspector();
      } else return;
      e.preventDefault();
    };
    window.addEventListener('keydown', onKey);
    return () => window.removeEventListener('keydown', onKey);
  }, [store, flow, pointer, wrapper, paletteOpen, openPalette, toggleInspector]);
}
