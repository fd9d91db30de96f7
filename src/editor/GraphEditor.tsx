/**
 * The node editor (React Flow). The GraphDoc in the store is the only truth: React Flow's nodes
 * are rebuilt from it; drags, wires, deletes and pastes become Changes (one undo step each).
 */
import {
  applyNodeChanges,
  Background,
  BackgroundVariant,
  type Connection,
  Controls,
  type Edge,
  type EdgeChange,
  MiniMap,
  type NodeChange,
  ReactFlow,
  useReactFlow,
} from '@xyflow/react';
import { useCallback, useEffect, useMemo, useRef, useState } from 'react';
import type { Diagnostic } from '../../nodes/core/diagnostics.ts';
import type { Evaluation } from '../../nodes/graph/evaluate.ts';
import { registry } from '../../nodes/types/index.ts';
import type { Change } from '../state/changes.ts';
import { idAllocator } from '../state/ids.ts';
import { useEditorState, useStore } from '../state/use-store.ts';
import { checkConnection, portOfHandle } from './connection.ts';
import { fixPatches } from './diagnostic-fix.ts';
import { type EditorActions, EditorContext } from './editor-context.ts';
import { diagnosticsByNode, type KfNode, type KfNodeData, toFlowEdges, toFlowNodes } from './flow-model.ts';
import { GraphToolbar } from './GraphToolbar.tsx';
import { InspectorDock } from './InspectorDock.tsx';
import { useKeepInView } from './keep-in-view.ts';
import { NodeView } from './NodeView.tsx';
import { gridPosition } from './new-node.ts';
import { Palette } from './Palette.tsx';
import { useFrameGraph } from './use-frame-graph.ts';
import { useGraphKeys } from './use-graph-keys.ts';
import { usePalette } from './use-palette.ts';
import { useRememberedFlag } from './use-remembered-flag.ts';

const nodeTypes = { kf: NodeView };

interface Props {
  readonly evaluation: Evaluation;
  /** Diagnostics from the renderer (e.g. a shader error), shown on their nodes too. */
  readonly extraDiagnostics: readonly Diagnostic[];
  readonly hoveredNodeId: string | null;
  /** Changes when a document is loaded: the graph is framed again. */
  readonly frameKey: number;
  onHoverNode(id: string | null): void;
  /** The phone's Inspector tab: the inspector is open and covers the pane. */
  readonly inspectorTab?: boolean;
}

export function GraphEditor({
  evaluation,
  extraDiagnostics,
  hoveredNodeId,
  frameKey,
  onHoverNode,
  inspectorTab = false,
}: Props) {
  const store = useStore();
  const doc = useEditorState((s) => s.doc);
  const selection = useEditorState((s) => s.selection);
  const flow = useReactFlow<KfNode, Edge>();
  const [nodes, setNodes] = useState<KfNode[]>([]);
  const [selectedEdges, setSelectedEdges] = useState<ReadonlySet<string>>(new Set());
  const [inspectorRemembered, setInspectorOpen] = useRememberedFlag('kleinflow.inspector', false);
  const inspectorOpen = inspectorRemembered || inspectorTab;
  const pointer = useRef<{ x: number; y: number } | null>(null);
  const wrapper = useRef<HTMLDivElement>(null);
  const inspectorButton = useRef<HTMLButtonElement>(null);

  const diagnostics = useMemo(
    () => diagnosticsByNode([...evaluation.diagnostics, ...extraDiagnostics]),
    [evaluation, extraDiagnostics],
  );

  useEffect(() => {
    setNodes((prev) =>
      toFlowNodes(
        doc,
        registry,
        evaluation.nodes,
        diagnostics,
        selection,
        hoveredNodeId,
        new Map(prev.map((n) => [n.id, n])),
      ),
    );
  }, [doc, evaluation, diagnostics, selection, hoveredNodeId]);
  const edges = useMemo(() => toFlowEdges(doc, registry, selectedEdges), [doc, selectedEdges]);

  // The fix maps handle moves with the evaluation current at the click, not the one at mount.
  const latestEvaluation = useRef(evaluation);
  latestEvaluation.current = evaluation;
  const actions = useMemo<EditorActions>(
    () => ({
      registry,
      editParam: (nodeId, key) => (value, final) => {
        const change: Change = { type: 'set-params', patches: [{ nodeId, params: { [key]: value } }] };
        if (final) store.commit(change, `edit ${key}`);
        else store.preview(change);
      },
      setHoveredNode: onHoverNode,
      runFix: (fix) =>
        store.dispatch({ type: 'set-params', patches: fixPatches(latestEvaluation.current, fix) }, fix.label),
    }),
    [store, onHoverNode],
  );

  const onNodesChange = useCallback(
    (changes: NodeChange<KfNode>[]) => {
      const kept = changes.filter((c) => c.type !== 'remove');
      setNodes((prev) => {
        const next = applyNodeChanges(kept, prev);
        if (kept.some((c) => c.type === 'select')) {
          queueMicrotask(() => store.setSelection(next.filter((n) => n.selected).map((n) => n.id)));
        }
        return next;
      });
    },
    [store],
  );
  const onEdgesChange = useCallback((changes: EdgeChange[]) => {
    setSelectedEdges((prev) => {
      const next = new Set(prev);
      for (const c of changes) {
        if (c.type === 'select') c.selected ? next.add(c.id) : next.delete(c.id);
        if (c.type === 'remove') next.delete(c.id);
      }
      return next;
    });
  }, []);

  const onDelete = useCallback(
    ({ nodes: ns, edges: es }: { nodes: KfNode[]; edges: Edge[] }) => {
      if (ns.length + es.length === 0) return;
      store.dispatch(
        { type: 'remove', nodeIds: ns.map((n) => n.id), edgeIds: es.map((e) => e.id) },
        'delete',
      );
    },
    [store],
  );

  const onNodeDragStop = useCallback(
    (_e: unknown, _node: KfNode, dragged: KfNode[]) => {
      const current = store.getState().doc;
      const moves = dragged
        .map((n) => ({
          nodeId: n.id,
          position: gridPosition(n.position.x, n.position.y),
        }))
        .filter((m) => {
          const before = current.nodes.find((n) => n.id === m.nodeId)?.position;
          return before && (before[0] !== m.position[0] || before[1] !== m.position[1]);
        });
      if (moves.length > 0) store.dispatch({ type: 'move-nodes', moves }, 'move nodes');
    },
    [store],
  );

  const isValidConnection = useCallback(
    (c: Connection | Edge) => checkConnection(store.getState().doc, registry, c).ok,
    [store],
  );
  const onConnect = useCallback(
    (c: Connection) => {
      const current = store.getState().doc;
      if (!checkConnection(current, registry, c).ok) return;
      const edge = {
        id: idAllocator(current)('e'),
        from: { node: c.source, port: portOfHandle(c.sourceHandle) },
        to: { node: c.target, port: portOfHandle(c.targetHandle) },
      };
      store.dispatch({ type: 'connect', edge }, 'connect');
    },
    [store],
  );

  const {
    palette,
    openPalette,
    openPaletteAt,
    openPaletteCentred,
    onConnectEnd,
    addFromPalette,
    closePalette,
  } = usePalette(wrapper);
  useFrameGraph(frameKey, doc, nodes, wrapper);

  const toggleInspector = useCallback(
    () => setInspectorOpen(!inspectorOpen),
    [inspectorOpen, setInspectorOpen],
  );
  useGraphKeys({
    store,
    flow,
    pointer,
    paletteOpen: palette !== null,
    openPalette: openPaletteAt,
    toggleInspector,
  });

  const inspected = selection.size === 1 ? doc.nodes.find((n) => selection.has(n.id)) : undefined;
  const inspectedData = inspected ? nodes.find((n) => n.id === inspected.id)?.data : undefined;
  useKeepInView(inspectorOpen && !inspectorTab ? inspected?.id : undefined, wrapper);

  return (
    <EditorContext.Provider value={actions}>
      <div className={inspectorTab ? 'kf-graph-area kf-graph-area--inspector-tab' : 'kf-graph-area'}>
        <GraphToolbar
          nodes={nodes}
          inspectorOpen={inspectorOpen}
          inspectorButton={inspectorButton}
          toggleInspector={toggleInspector}
          onAddNode={openPaletteCentred}
        />
        <div className="kf-graph-area__body">
          {/* biome-ignore lint/a11y/noStaticElementInteractions: tracks the pointer (where new nodes land); React Flow is the interactive canvas */}
          <div
            className="kf-graph"
            ref={wrapper}
            onPointerMove={(e) => {
              pointer.current = { x: e.clientX, y: e.clientY };
            }}
            onPointerLeave={() => {
              pointer.current = null;
            }}
            onDoubleClick={(e) => {
              if ((e.target as Element).classList.contains('react-flow__pane'))
                openPalette({ x: e.clientX, y: e.clientY });
            }}
          >
            <ReactFlow<KfNode, Edge>
              nodes={nodes}
              edges={edges}
              nodeTypes={nodeTypes}
              onNodesChange={onNodesChange}
              onEdgesChange={onEdgesChange}
              onDelete={onDelete}
              onNodeDragStop={onNodeDragStop}
              onConnect={onConnect}
              onConnectEnd={onConnectEnd}
              isValidConnection={isValidConnection}
              deleteKeyCode={['Delete', 'Backspace']}
              selectionKeyCode="Shift"
              panActivationKeyCode={null}
              multiSelectionKeyCode={['Meta', 'Control']}
              zoomOnDoubleClick={false}
              colorMode="dark"
              minZoom={0.15}
              maxZoom={2.5}
              attributionPosition="top-left"
              defaultEdgeOptions={{ interactionWidth: 16 }}
              connectionRadius={24}
            >
              <Background variant={BackgroundVariant.Dots} gap={22} size={1.2} color="#2c2f36" />
              <MiniMap
                style={{ width: 150, height: 100 }}
                pannable
                zoomable
                nodeColor={(n) => (n.data as KfNodeData).def?.color ?? '#e5484d'}
                nodeStrokeWidth={0}
                maskColor="rgba(12, 13, 16, 0.7)"
                ariaLabel="Graph overview"
              />
              <Controls showInteractive={false} />
            </ReactFlow>
            {doc.nodes.length === 0 && (
              <div className="kf-empty-hint">
                <p>
                  <kbd>Space</kbd>, double-click or <strong>Add node</strong> to add a node
                </p>
                <p>or open an example from the menu</p>
              </div>
            )}
          </div>
          {inspectorOpen && (
            <InspectorDock
              node={inspected}
              fill={inspectorTab}
              connected={inspectedData?.connected ?? new Set()}
              evaluation={inspected && evaluation.nodes.get(inspected.id)}
              diagnostics={(inspected && diagnostics.get(inspected.id)) ?? []}
              onLabel={(label) =>
                inspected && store.dispatch({ type: 'set-label', nodeId: inspected.id, label }, 'rename')
              }
              onClose={(fromKeyboard) => {
                toggleInspector();
                // The panel and its focused control are gone: keep the keyboard user on its toggle.
                if (fromKeyboard) inspectorButton.current?.focus();
              }}
            />
          )}
        </div>
      </div>
      {palette && (
        <Palette
          defs={registry.all}
          at={palette.screen}
          filter={palette.filter}
          onPick={addFromPalette}
          onClose={closePalette}
        />
      )}
    </EditorContext.Provider>
  );
}
