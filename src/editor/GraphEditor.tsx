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
import { idAtLevel, type NodePath } from '../../nodes/graph/flatten.ts';
import { registry } from '../../nodes/types/index.ts';
import type { Change } from '../state/changes.ts';
import { idAllocator } from '../state/ids.ts';
import { StoreContext, useEditorState, useStore } from '../state/use-store.ts';
import { checkConnection, portOfHandle } from './connection.ts';
import { fixPatches } from './diagnostic-fix.ts';
import { EditorProviders } from './EditorProviders.tsx';
import type { EditorActions } from './editor-context.ts';
import { diagnosticsByNode, type KfNode, type KfNodeData, toFlowEdges, toFlowNodes } from './flow-model.ts';
import { GraphToolbar } from './GraphToolbar.tsx';
import { InspectorDock } from './InspectorDock.tsx';
import { useKeepInView } from './keep-in-view.ts';
import { NodeView } from './NodeView.tsx';
import { gridPosition } from './new-node.ts';
import { Palette } from './Palette.tsx';
import { renderNodeSuggestion } from './render-node-suggestion.ts';
import { type FrameNode, FrameView, isFrameId } from './tools/FrameView.tsx';
import { GroupBreadcrumb, type GroupScope, useGroupScope } from './tools/GroupScope.tsx';
import { insertMyGroup, readMyGroups, type SavedGroup } from './tools/my-groups.ts';
import { RerouteEdge } from './tools/RerouteEdge.tsx';
import { insertVia } from './tools/reroute.ts';
import { useFrames } from './tools/use-frames.ts';
import { useFrameGraph } from './use-frame-graph.ts';
import { useGraphA11y } from './use-graph-a11y.ts';
import { useGraphKeys } from './use-graph-keys.ts';
import { usePalette } from './use-palette.ts';
import { useRememberedFlag } from './use-remembered-flag.ts';

const nodeTypes = { kf: NodeView, frame: FrameView };
const edgeTypes = { kf: RerouteEdge };
type AnyNode = KfNode | FrameNode;

interface Props {
  readonly evaluation: Evaluation;
  /** Diagnostics from the renderer (e.g. a shader error), shown on their nodes too. */
  readonly extraDiagnostics: readonly Diagnostic[];
  /** The hovered node's document path (shared with the render): at this level, the node holding it. */
  readonly hovered: NodePath | null;
  /** Changes when a document is loaded: the graph is framed again. */
  readonly frameKey: number;
  onHover(path: NodePath | null): void;
  /** The phone's Inspector tab: the inspector is open and covers the pane. */
  readonly inspectorTab?: boolean;
}

/**
 * The editor at one level of groups (docs/architecture.md "Groups"): the document, store and
 * evaluation it sees are the open group's (tools/GroupScope.tsx), the top level when none is open.
 */
export function GraphEditor(props: Props) {
  const scope = useGroupScope(props.evaluation, props.frameKey, props.extraDiagnostics);
  return (
    <StoreContext.Provider value={scope.store}>
      <GraphCanvas
        {...props}
        evaluation={scope.evaluation}
        extraDiagnostics={scope.extraDiagnostics}
        frameKey={scope.frameKey}
        scope={scope}
      />
    </StoreContext.Provider>
  );
}

function GraphCanvas({
  evaluation,
  extraDiagnostics,
  hovered,
  frameKey,
  onHover,
  inspectorTab = false,
  scope,
}: Props & { readonly scope: GroupScope }) {
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

  const hoveredNodeId = hovered && idAtLevel(hovered, scope.path);
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
  const edges: Edge[] = useMemo(() => toFlowEdges(doc, registry, selectedEdges), [doc, selectedEdges]);

  // The fix maps handle moves with the evaluation current at the click, not the one at mount.
  const actions = useMemo<EditorActions>(
    () => ({
      registry,
      editParam: (nodeId, key) => (value, final) => {
        const change: Change = { type: 'set-params', patches: [{ nodeId, params: { [key]: value } }] };
        if (final) store.commit(change, `edit ${key}`);
        else store.preview(change);
      },
      setHoveredNode: (id) => onHover(id === null ? null : [...scope.path, id]),
      // Fixes name nodes by their flattened ids: run on the whole document (routed into groups).
      runFix: (fix) =>
        scope.base.dispatch({ type: 'set-params', patches: fixPatches(scope.full.current, fix) }, fix.label),
      openGroup: scope.open,
    }),
    [store, onHover, scope.path, scope.base, scope.full, scope.open],
  );

  const frames = useFrames(doc, store, setNodes);
  const { onFrameChanges } = frames;

  const onNodesChange = useCallback(
    (all: NodeChange<AnyNode>[]) => {
      const frameChanges = all.filter((c) => 'id' in c && isFrameId(c.id)) as NodeChange<FrameNode>[];
      if (frameChanges.length > 0) onFrameChanges(frameChanges);
      const changes = all.filter((c) => !('id' in c && isFrameId(c.id))) as NodeChange<KfNode>[];
      const kept = changes.filter((c) => c.type !== 'remove');
      setNodes((prev) => {
        const next = applyNodeChanges(kept, prev);
        if (kept.some((c) => c.type === 'select')) {
          queueMicrotask(() => store.setSelection(next.filter((n) => n.selected).map((n) => n.id)));
        }
        return next;
      });
    },
    [store, onFrameChanges],
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
    ({ nodes: all, edges: es }: { nodes: AnyNode[]; edges: Edge[] }) => {
      const ns = all.filter((n) => !isFrameId(n.id));
      const frameIds = all.filter((n) => isFrameId(n.id)).map((n) => (n as FrameNode).data.frame.id);
      if (all.length + es.length === 0) return;
      const remove: Change = { type: 'remove', nodeIds: ns.map((n) => n.id), edgeIds: es.map((e) => e.id) };
      store.dispatch(
        frameIds.length > 0
          ? { type: 'batch', changes: [remove, { type: 'remove-frames', frameIds }] }
          : remove,
        'delete',
      );
    },
    [store],
  );

  const { onFrameDrag, onFrameDragStop } = frames;
  const onNodeDrag = useCallback(
    (_e: unknown, node: AnyNode) => {
      if (node.type === 'frame') onFrameDrag(node);
    },
    [onFrameDrag],
  );
  const onNodeDragStop = useCallback(
    (_e: unknown, node: AnyNode, all: AnyNode[]) => {
      if (node.type === 'frame') return onFrameDragStop(node);
      const dragged = all.filter((n): n is KfNode => n.type === 'kf');
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
    [store, onFrameDragStop],
  );

  /** Double-clicking a wire adds a reroute point there. */
  const onEdgeDoubleClick = useCallback(
    (e: React.MouseEvent, edge: Edge) => {
      const current = store.getState().doc;
      const stored = current.edges.find((x) => x.id === edge.id);
      const internal = flow.getInternalNode(edge.source);
      const internalTarget = flow.getInternalNode(edge.target);
      if (!stored || !internal || !internalTarget) return;
      e.stopPropagation();
      const p = flow.screenToFlowPosition({ x: e.clientX, y: e.clientY });
      const src = internal.internals.positionAbsolute;
      const dst = internalTarget.internals.positionAbsolute;
      const source = [src.x + (internal.measured.width ?? 0), src.y] as const;
      const via = insertVia(source, stored.via ?? [], [dst.x, dst.y], gridPosition(p.x, p.y));
      store.dispatch({ type: 'set-via', edgeId: edge.id, via }, 'add reroute point');
    },
    [store, flow],
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

  const keyboardWire = useGraphA11y({
    doc,
    getDoc: useCallback(() => store.getState().doc, [store]),
    registry,
    selection,
    diagnostics: evaluation.diagnostics,
    onConnect,
    wrapper,
  });

  const {
    palette,
    openPalette,
    openPaletteAt,
    openPaletteCentred,
    onConnectEnd,
    addFromPalette,
    closePalette,
    lastAdded,
  } = usePalette(wrapper);

  const addSavedGroup = useCallback(
    (saved: SavedGroup) => {
      if (!palette) return;
      const { change, nodeId } = insertMyGroup(store.getState().doc, saved, palette.flow);
      store.dispatch(change, `add ${saved.name}`);
      store.setSelection([nodeId]);
      closePalette();
    },
    [palette, store, closePalette],
  );

  useFrameGraph(frameKey, doc, nodes, wrapper);
  const allNodes = useMemo<AnyNode[]>(() => [...frames.frameNodes, ...nodes], [frames.frameNodes, nodes]);

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
    openGroup: scope.open,
  });

  const inspected = selection.size === 1 ? doc.nodes.find((n) => selection.has(n.id)) : undefined;
  const inspectedData = inspected ? nodes.find((n) => n.id === inspected.id)?.data : undefined;
  // The selected node stays in view: one picked elsewhere (the status bar's warnings list) is
  // panned to, one kept inspected in the docked panel is not hidden behind it, and one just added
  // from the palette is shown.
  useKeepInView(inspectorTab ? undefined : (inspected?.id ?? lastAdded), wrapper, inspectorOpen);

  return (
    <EditorProviders actions={actions} wire={keyboardWire}>
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
            // The phone's Inspector tab covers the canvas: what it hides takes no focus, so Tab goes
            // straight into the inspector instead of through every hidden port and field.
            inert={inspectorTab}
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
            <ReactFlow<AnyNode, Edge>
              nodes={allNodes}
              edges={edges}
              nodeTypes={nodeTypes}
              edgeTypes={edgeTypes}
              onNodeDrag={onNodeDrag}
              onNodeDoubleClick={(_e, n) => n.type === 'kf' && n.data.node.group && scope.open(n.id)}
              onEdgeDoubleClick={onEdgeDoubleClick}
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
                nodeColor={(n) =>
                  n.type === 'frame' ? 'transparent' : ((n.data as KfNodeData).def?.color ?? '#e5484d')
                }
                nodeStrokeWidth={0}
                maskColor="rgba(12, 13, 16, 0.7)"
                ariaLabel="Graph overview"
              />
              <Controls showInteractive={false} />
            </ReactFlow>
            <GroupBreadcrumb scope={scope} />
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
              suggested={renderNodeSuggestion(doc, evaluation)}
              onInspect={(id) => store.setSelection([id])}
              fill={inspectorTab}
              connected={inspectedData?.connected ?? new Set()}
              evaluation={inspected && evaluation.nodes.get(inspected.id)}
              diagnostics={(inspected && diagnostics.get(inspected.id)) ?? []}
              onLabel={(label) =>
                inspected && store.dispatch({ type: 'set-label', nodeId: inspected.id, label }, 'rename')
              }
              onMute={(muted) =>
                inspected &&
                store.dispatch(
                  { type: 'set-muted', nodeIds: [inspected.id], muted },
                  muted ? 'mute' : 'unmute',
                )
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
          saved={readMyGroups()}
          onPickSaved={addSavedGroup}
          onClose={closePalette}
        />
      )}
    </EditorProviders>
  );
}
