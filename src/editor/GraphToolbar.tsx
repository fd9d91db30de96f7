/**
 * The graph pane's toolbar, a strip above the canvas (so it never covers a node): Add node (the
 * search palette, for touch screens without a keyboard), Tidy, the Inspector toggle, and the tools
 * for the selected nodes (Mute, Frame, Group, Ungroup).
 */

import { type Edge, useReactFlow } from '@xyflow/react';
import type { RefObject } from 'react';
import type { GraphNode } from '../../nodes/graph/document.ts';
import { registry } from '../../nodes/types/index.ts';
import { useEditorState, useStore } from '../state/use-store.ts';
import { motionMs } from '../ui/motion.ts';
import type { KfNode } from './flow-model.ts';
import { FIT_VIEW, sizer, tidyPositions } from './layout.ts';
import { SelectionTools } from './tools/SelectionTools.tsx';

interface Props {
  readonly nodes: readonly KfNode[];
  readonly inspectorOpen: boolean;
  /** The Inspector toggle, where focus returns when Esc closes the panel. */
  readonly inspectorButton: RefObject<HTMLButtonElement | null>;
  toggleInspector(): void;
  onAddNode(): void;
}

export function GraphToolbar({ nodes, inspectorOpen, inspectorButton, toggleInspector, onAddNode }: Props) {
  const store = useStore();
  const flow = useReactFlow<KfNode, Edge>();
  const empty = useEditorState((s) => s.doc.nodes.length === 0);

  /** Tidy layout with the sizes React Flow measured (estimates for nodes not drawn yet): one undo step. */
  const tidy = () => {
    const current = store.getState().doc;
    const estimate = sizer(current, registry);
    const measured = new Map(nodes.map((n) => [n.id, n.measured]));
    const size = (n: GraphNode) => {
      const m = measured.get(n.id);
      return m?.width && m.height ? { width: m.width, height: m.height } : estimate(n);
    };
    store.dispatch({ type: 'move-nodes', moves: tidyPositions(current, size, registry) }, 'tidy layout');
    requestAnimationFrame(() => void flow.fitView({ ...FIT_VIEW, duration: motionMs(200) }));
  };

  return (
    <div className="kf-graph-tools" role="toolbar" aria-label="Graph">
      <button
        type="button"
        className="kf-button"
        title="Search the node types and add one (Space)"
        onClick={onAddNode}
      >
        <span aria-hidden="true">+</span> Add node
      </button>
      <button
        type="button"
        className="kf-button"
        title="Arrange the nodes in columns from sources to the render"
        disabled={empty}
        onClick={tidy}
      >
        Tidy
      </button>
      <button
        ref={inspectorButton}
        type="button"
        className={`kf-button kf-graph-tools__inspector${inspectorOpen ? ' kf-button--active' : ''}`}
        aria-pressed={inspectorOpen}
        title="Show the inspector for the selected node (I)"
        onClick={(e) => {
          toggleInspector();
          // Opened by Enter or Space (a click with no pointer, detail 0): the panel comes after the
          // whole graph in the tab order, so the keyboard is taken to it rather than into the graph.
          if (!inspectorOpen && e.detail === 0)
            requestAnimationFrame(() => document.querySelector<HTMLElement>('.kf-inspector')?.focus());
        }}
      >
        Inspector
      </button>
      <SelectionTools />
    </div>
  );
}
