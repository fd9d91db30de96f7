/**
 * What floats over the graph canvas: the empty-graph hint, the Tidy and Inspector buttons, and the
 * inspector for the selected node.
 */
import { type Edge, useReactFlow } from '@xyflow/react';
import type { Diagnostic } from '../../nodes/core/diagnostics.ts';
import type { GraphNode } from '../../nodes/graph/document.ts';
import type { Evaluation } from '../../nodes/graph/evaluate.ts';
import { registry } from '../../nodes/types/index.ts';
import { useEditorState, useStore } from '../state/use-store.ts';
import type { KfNode } from './flow-model.ts';
import { Inspector } from './Inspector.tsx';
import { FIT_VIEW, sizer, tidyPositions } from './layout.ts';
import { SelectionTools } from './tools/SelectionTools.tsx';

interface Props {
  readonly nodes: readonly KfNode[];
  readonly evaluation: Evaluation;
  readonly diagnostics: ReadonlyMap<string, readonly Diagnostic[]>;
  readonly inspectorOpen: boolean;
  toggleInspector(): void;
}

export function GraphPanels({ nodes, evaluation, diagnostics, inspectorOpen, toggleInspector }: Props) {
  const store = useStore();
  const flow = useReactFlow<KfNode, Edge>();
  const doc = useEditorState((s) => s.doc);
  const selection = useEditorState((s) => s.selection);

  /** Tidy layout with the sizes React Flow measured (estimates for nodes not drawn yet): one undo step. */
  const tidy = () => {
    const current = store.getState().doc;
    const estimate = sizer(current, registry);
    const measured = new Map(nodes.map((n) => [n.id, n.measured]));
    const size = (n: GraphNode) => {
      const m = measured.get(n.id);
      return m?.width && m.height ? { width: m.width, height: m.height } : estimate(n);
    };
    store.dispatch({ type: 'move-nodes', moves: tidyPositions(current, size) }, 'tidy layout');
    requestAnimationFrame(() => void flow.fitView({ ...FIT_VIEW, duration: 200 }));
  };

  const inspected = selection.size === 1 ? doc.nodes.find((n) => selection.has(n.id)) : undefined;
  const inspectedData = inspected ? nodes.find((n) => n.id === inspected.id)?.data : undefined;
  return (
    <>
      {doc.nodes.length === 0 && (
        <div className="kf-empty-hint">
          <p>
            <kbd>Space</kbd> or double-click to add a node
          </p>
          <p>or open an example from the menu</p>
        </div>
      )}
      <div className="kf-graph-tools">
        <button
          type="button"
          className="kf-button"
          title="Arrange the nodes in columns from sources to the render"
          disabled={doc.nodes.length === 0}
          onClick={tidy}
        >
          Tidy
        </button>
        <button
          type="button"
          className={`kf-button${inspectorOpen ? ' kf-button--active' : ''}`}
          aria-pressed={inspectorOpen}
          title="Show the inspector for the selected node (I)"
          onClick={toggleInspector}
        >
          Inspector
        </button>
        <SelectionTools />
      </div>
      {inspectorOpen && !inspected && (
        <aside className="kf-inspector kf-inspector--empty" aria-label="Inspector">
          Select one node to inspect it.
        </aside>
      )}
      {inspectorOpen && inspected && (
        <Inspector
          node={inspected}
          connected={inspectedData?.connected ?? new Set()}
          evaluation={evaluation.nodes.get(inspected.id)}
          diagnostics={diagnostics.get(inspected.id) ?? []}
          onLabel={(label) => store.dispatch({ type: 'set-label', nodeId: inspected.id, label }, 'rename')}
          onMute={(muted) =>
            store.dispatch({ type: 'set-muted', nodeIds: [inspected.id], muted }, muted ? 'mute' : 'unmute')
          }
          onClose={toggleInspector}
        />
      )}
    </>
  );
}
