/**
 * The render overlay's keyboard: each handle is named for a screen reader ("Point A, p") and arrow
 * keys move the focused one (handle-keys.ts), committed at once as one undo step and announced.
 */
import { type KeyboardEvent, useMemo } from 'react';
import type { HandleItem } from '../../../nodes/core/scene.ts';
import type { Vec2 } from '../../../nodes/core/values.ts';
import type { GraphDoc } from '../../../nodes/graph/document.ts';
import type { NodePatch } from '../../../nodes/graph/drag-patches.ts';
import type { Evaluation } from '../../../nodes/graph/evaluate.ts';
import { announce } from '../../ui/announce.ts';
import { handleKeyPatches } from './handle-keys.ts';
import type { Screen } from './screen.ts';

interface Inputs {
  readonly doc: GraphDoc;
  readonly evaluation: Evaluation;
  readonly onCommit: (patches: NodePatch[]) => void;
}

const fmt = (v: number) => (Math.round(v * 100) / 100).toString();

export function useHandleKeyboard(props: Inputs, screen: Screen, enabled: boolean) {
  const { doc, evaluation, onCommit } = props;
  return useMemo(() => {
    if (!enabled) return undefined;
    const nodeName = (id: string) => {
      const label = doc.nodes.find((n) => n.id === id)?.label;
      const type = evaluation.analysis.nodes.get(id)?.def?.label ?? 'node';
      return label ? `${label}, ${type}` : type;
    };
    return {
      name: (item: HandleItem) =>
        `${nodeName(item.nodeId)} ${item.handle} at ${fmt(item.at[0])}, ${fmt(item.at[1])}: arrow keys move it`,
      onKey: (item: HandleItem, at: Vec2, e: KeyboardEvent<SVGCircleElement>) => {
        const patches = handleKeyPatches(e, item, at, screen, evaluation);
        if (!patches) return;
        // The arrows are the handle's: not the page's scroll nor the pane's pan.
        e.preventDefault();
        e.stopPropagation();
        if (patches.length === 0) return;
        onCommit(patches);
        announce(`${nodeName(item.nodeId)} moved`);
      },
    };
  }, [enabled, doc, evaluation, onCommit, screen]);
}
