/**
 * A tiny page for the Chromium test: RenderOverlay over a stand-in canvas, wired like the editor
 * wires it (previews applied on top of the committed document, commits replace it, everything
 * re-evaluated). Calls are logged on window.overlayLog; the pane's own pointerdown listener logs
 * what a pan/zoom handler would see.
 */
import { type JSX, useMemo, useState } from 'react';
import { createRoot } from 'react-dom/client';
import type { GraphDoc } from '../../../../../nodes/graph/document.ts';
import { evaluateGraph } from '../../../../../nodes/graph/evaluate.ts';
import { registry } from '../../../../../nodes/types/index.ts';
import { type NodePatch, RenderOverlay } from '../../../../../src/viewport/overlay/RenderOverlay.tsx';
import { overlayDoc } from '../fixtures.ts';

export type LogEntry =
  | { kind: 'preview'; patches: NodePatch[] }
  | { kind: 'commit'; patches: NodePatch[] }
  | { kind: 'hover'; id: string | null }
  | { kind: 'pane-pointerdown'; prevented: boolean };

declare global {
  interface Window {
    overlayLog: LogEntry[];
  }
}
window.overlayLog = [];
const log = (entry: LogEntry) => window.overlayLog.push(JSON.parse(JSON.stringify(entry)));

const SIZE = 600;

function apply(doc: GraphDoc, patches: readonly NodePatch[]): GraphDoc {
  return {
    ...doc,
    nodes: doc.nodes.map((n) => {
      const p = patches.find((q) => q.nodeId === n.id);
      return p ? { ...n, params: { ...n.params, ...p.params } } : n;
    }),
  };
}

function Harness(): JSX.Element {
  const [committed, setCommitted] = useState(overlayDoc);
  const [preview, setPreview] = useState<NodePatch[]>([]);
  const [hovered, setHovered] = useState<string | null>(null);
  const doc = useMemo(() => apply(committed, preview), [committed, preview]);
  const evaluation = useMemo(() => evaluateGraph(doc, registry), [doc]);
  return (
    <div
      id="pane"
      style={{ position: 'relative', width: SIZE, height: SIZE, background: 'linear-gradient(#234, #a86)' }}
      ref={(el) => {
        if (el && !el.dataset.listening) {
          el.dataset.listening = '1';
          el.addEventListener('pointerdown', (e) =>
            log({ kind: 'pane-pointerdown', prevented: e.defaultPrevented }),
          );
        }
      }}
    >
      <RenderOverlay
        doc={doc}
        evaluation={evaluation}
        view={doc.view}
        width={SIZE}
        height={SIZE}
        hoveredNodeIds={new Set(hovered ? [hovered] : [])}
        onHoverNode={(id) => {
          log({ kind: 'hover', id });
          setHovered(id);
        }}
        onPreview={(patches) => {
          log({ kind: 'preview', patches });
          setPreview(patches);
        }}
        onCommit={(patches) => {
          log({ kind: 'commit', patches });
          setCommitted((d) => apply(d, patches));
          setPreview([]);
        }}
        showLabels
      />
    </div>
  );
}

createRoot(document.getElementById('root')!).render(<Harness />);
