/**
 * The Export menu's "Animation…" item and its dialog (AnimationExportDialog), kept out of
 * use-document-io.tsx: it adds one menu item and one piece of UI there.
 */
import { type ReactNode, useState } from 'react';
import { evaluateGraph } from '../../../nodes/graph/evaluate.ts';
import { loopPeriod } from '../../../nodes/graph/loop-period.ts';
import { registry } from '../../../nodes/types/index.ts';
import type { EditorStore } from '../../state/store.ts';
import type { Viewport } from '../../viewport/viewport.ts';
import { type AnimationExportOptions, exportAnimation } from '../animation-export.ts';
import type { MenuItem } from '../Menu.tsx';
import { AnimationExportDialog } from './AnimationExportDialog.tsx';
import type { Size } from './ExportDialog.tsx';

interface Options {
  readonly store: EditorStore;
  /** The render node's sample count (the dialog starts at least there). */
  readonly samples: number;
  viewport(): Viewport | null;
  viewSize(): Size;
  say(kind: 'ok' | 'error', text: string): void;
}

export function useAnimationExport({ store, samples, viewport, viewSize, say }: Options): {
  item: MenuItem;
  ui: ReactNode;
} {
  const [open, setOpen] = useState(false);
  const item: MenuItem = {
    label: 'Animation…',
    hint: 'WebM, MP4 or GIF, frame by frame',
    onSelect: () => setOpen(true),
  };
  if (!open) return { item, ui: null };
  const doc = store.getState().doc;
  const run = async (o: AnimationExportOptions, onProgress: (f: number) => boolean) => {
    const v = viewport();
    if (!v) throw new Error('the WebGL2 renderer is not running');
    const done = await exportAnimation(v, store.getState().doc, o, onProgress);
    if (done) say('ok', `Exported ${o.frames} frames at ${o.fps} fps (${o.width} × ${o.height}).`);
    return done;
  };
  const ui = (
    <AnimationExportDialog
      viewSize={viewSize()}
      view={doc.view}
      defaultSamples={Math.max(samples, 8)}
      loop={loopPeriod(doc, evaluateGraph(doc, registry))}
      run={run}
      onClose={() => setOpen(false)}
    />
  );
  return { item, ui };
}
