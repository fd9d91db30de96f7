/** What every node component needs besides its own data: the registry and the edit callbacks. */
import { createContext, useContext } from 'react';
import type { DiagnosticFix } from '../../nodes/core/diagnostics.ts';
import type { NodeRegistry } from '../../nodes/core/registry.ts';
import type { OnEdit } from './widgets/edit.ts';

export interface EditorActions {
  readonly registry: NodeRegistry;
  /** Edit one stored param/inline input of a node (preview while `final` is false). */
  editParam(nodeId: string, key: string): OnEdit<unknown>;
  /** The node under the pointer (shared with the render overlay). */
  setHoveredNode(id: string | null): void;
  /** Runs a diagnostic's fix as one undo step. */
  runFix(fix: DiagnosticFix): void;
  /** Opens a group node to edit inside it. */
  openGroup(nodeId: string): void;
}

export const EditorContext = createContext<EditorActions | null>(null);

export function useEditorActions(): EditorActions {
  const ctx = useContext(EditorContext);
  if (!ctx) throw new Error('useEditorActions outside <EditorContext.Provider>');
  return ctx;
}
