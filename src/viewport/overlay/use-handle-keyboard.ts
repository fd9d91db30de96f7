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

export const fmt = (v: number) => (Math.round(v * 100) / 100).toString();

/** What HandleKnobs takes to make its knobs keyboard handles: a name and a key handler per handle. */
export interface HandleKeyboard<T> {
  readonly name: (item: T) => string;
  readonly onKey: (item: T, at: Vec2, e: KeyboardEvent<SVGCircleElement>) => void;
}

/**
 * The keyboard of a 2D or 3D overlay: handle `item` is named "<node name> <handle> <where>", and a
 * key for which `patches` has an answer is the handle's (not the page's scroll nor the pane's pan or
 * orbit); a non-empty answer is committed as one undo step and announced.
 */
export function handleKeyboard<T extends { readonly nodeId: string; readonly handle: string }>(
  nodeName: (id: string) => string,
  where: (item: T) => string,
  patches: (item: T, at: Vec2, e: KeyboardEvent<SVGCircleElement>) => NodePatch[] | null,
  onCommit: (patches: NodePatch[]) => void,
): HandleKeyboard<T> {
  return {
    name: (item) => `${nodeName(item.nodeId)} ${item.handle} ${where(item)}`,
    onKey: (item, at, e) => {
      const found = patches(item, at, e);
      if (!found) return;
      e.preventDefault();
      e.stopPropagation();
      if (found.length === 0) return;
      onCommit(found);
      announce(`${nodeName(item.nodeId)} moved`);
    },
  };
}

export function useHandleKeyboard(props: Inputs, screen: Screen, enabled: boolean) {
  const { doc, evaluation, onCommit } = props;
  return useMemo(() => {
    if (!enabled) return undefined;
    const nodeName = (id: string) => {
      const label = doc.nodes.find((n) => n.id === id)?.label;
      const type = evaluation.analysis.nodes.get(id)?.def?.label ?? 'node';
      return label ? `${label}, ${type}` : type;
    };
    return handleKeyboard<HandleItem>(
      nodeName,
      (item) => `at ${fmt(item.at[0])}, ${fmt(item.at[1])}: arrow keys move it`,
      (item, at, e) => handleKeyPatches(e, item, at, screen, evaluation),
      onCommit,
    );
  }, [enabled, doc, evaluation, onCommit, screen]);
}
