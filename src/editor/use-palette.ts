/**
 * The search palette's state in the graph editor: opened at a screen point (Space, double-click,
 * the Add node button, or a wire dropped on empty canvas, then filtered to the types that fit it),
 * and the pick that adds the node there as one undo step, selected.
 */
import { type Edge, type FinalConnectionState, useReactFlow } from '@xyflow/react';
import { type RefObject, useCallback, useState } from 'react';
import type { NodeDef } from '../../nodes/core/define-node.ts';
import { portSpec } from '../../nodes/core/port-lookup.ts';
import { useStore } from '../state/use-store.ts';
import { portOfHandle } from './connection.ts';
import type { KfNode, KfNodeData } from './flow-model.ts';
import { addNodeChange, type PaletteState } from './palette-actions.ts';

export function usePalette(wrapper: RefObject<HTMLDivElement | null>) {
  const store = useStore();
  const flow = useReactFlow<KfNode, Edge>();
  const [palette, setPalette] = useState<PaletteState | null>(null);
  const closePalette = useCallback(() => setPalette(null), []);
  /** The node the last pick added (the editor pans to keep it in view). */
  const [lastAdded, setLastAdded] = useState<string | undefined>(undefined);

  const openPalette = useCallback(
    (screen: { x: number; y: number }, extra: Partial<PaletteState> = {}) => {
      setPalette({ screen, flow: flow.screenToFlowPosition(screen), ...extra });
    },
    [flow],
  );

  /** A wire dropped on empty canvas opens the palette filtered to types that fit it. */
  const onConnectEnd = useCallback(
    (event: MouseEvent | TouchEvent, state: FinalConnectionState) => {
      if (state.isValid || !state.fromHandle || !state.fromNode) return;
      const target = event.target as Element | null;
      if (!target?.classList.contains('react-flow__pane')) return;
      const data = state.fromNode.data as KfNodeData;
      const port = portOfHandle(state.fromHandle.id);
      const side = state.fromHandle.type;
      const type = portSpec(data.def, side === 'source' ? 'outputs' : 'inputs', port)?.type;
      if (!type) return;
      const point = 'changedTouches' in event ? event.changedTouches[0] : event;
      openPalette(
        { x: point.clientX, y: point.clientY },
        {
          filter: { from: side, type },
          wire: { nodeId: state.fromNode.id, handle: state.fromHandle.id ?? '', side },
        },
      );
    },
    [openPalette],
  );

  const addFromPalette = useCallback(
    (def: NodeDef) => {
      if (!palette) return;
      const { change, nodeId } = addNodeChange(store.getState().doc, def, palette);
      store.dispatch(change, `add ${def.label}`);
      store.setSelection([nodeId]);
      setLastAdded(nodeId);
      setPalette(null);
    },
    [palette, store],
  );

  /** Where a palette opened without a pointer position (keyboard, the Add node button) appears. */
  const openPaletteCentred = useCallback(() => {
    const rect = wrapper.current!.getBoundingClientRect();
    openPalette({ x: rect.left + rect.width / 2, y: rect.top + rect.height / 3 }, { centred: true });
  }, [openPalette, wrapper]);
  const openPaletteAt = useCallback(
    (at: { x: number; y: number } | null) => (at ? openPalette(at) : openPaletteCentred()),
    [openPalette, openPaletteCentred],
  );

  return {
    palette,
    openPalette,
    openPaletteAt,
    openPaletteCentred,
    onConnectEnd,
    addFromPalette,
    closePalette,
    lastAdded,
  };
}
