/**
 * Which group the graph editor has open (docs/architecture.md "Groups"): the path of group ids from
 * the top, the scoped store and evaluation for that level, and the breadcrumb that leads back out.
 * The path is UI state, never saved; a group that disappears (undo, a loaded file) closes itself.
 */
import { type RefObject, useCallback, useEffect, useMemo, useRef, useState } from 'react';
import type { Diagnostic } from '../../../nodes/core/diagnostics.ts';
import type { Evaluation } from '../../../nodes/graph/evaluate.ts';
import { scopeDocument } from '../../state/group-changes.ts';
import { scopedStore } from '../../state/scoped-store.ts';
import type { EditorStore } from '../../state/store.ts';
import { useEditorState, useStore } from '../../state/use-store.ts';
import { scopeDiagnostics, scopeEvaluation } from './scope-evaluation.ts';

const NONE: readonly Diagnostic[] = [];

export interface GroupScope {
  readonly path: readonly string[];
  /** The label of each open group, outermost first. */
  readonly names: readonly string[];
  /** The open group's exposed ports ("inputs: a, b · outputs: c"), empty at the top level. */
  readonly ports: string;
  readonly base: EditorStore;
  readonly store: EditorStore;
  readonly evaluation: Evaluation;
  /** The renderer's diagnostics as shown at this level (scope-evaluation.ts scopeDiagnostics). */
  readonly extraDiagnostics: readonly Diagnostic[];
  /** The whole document's evaluation (flattened ids), current at any moment. */
  readonly full: RefObject<Evaluation>;
  /** Changes when the level changes or a document is loaded: the graph is framed again. */
  readonly frameKey: number;
  open(groupId: string): void;
  /** Back out to `depth` groups deep (0: the top level). */
  goTo(depth: number): void;
}

export function useGroupScope(
  evaluation: Evaluation,
  loadKey: number,
  rendererDiagnostics: readonly Diagnostic[] = NONE,
): GroupScope {
  const base = useStore();
  const doc = useEditorState((s) => s.doc);
  const [path, setPath] = useState<readonly string[]>([]);
  const [frameKey, setFrameKey] = useState(0);
  // biome-ignore lint/correctness/useExhaustiveDependencies: a new level or document is the trigger
  useEffect(() => setFrameKey((k) => k + 1), [loadKey, path]);
  useEffect(() => {
    if (path.length > 0 && !scopeDocument(doc, path)) setPath([]);
  }, [doc, path]);
  const store = useMemo(() => scopedStore(base, path), [base, path]);
  const scoped = useMemo(() => scopeEvaluation(evaluation, path, doc), [evaluation, path, doc]);
  // The renderer's diagnostics name flattened ids too: inside a group they go on the group's node.
  const extraDiagnostics = useMemo(
    () => scopeDiagnostics(rendererDiagnostics, evaluation, path, doc),
    [rendererDiagnostics, evaluation, path, doc],
  );
  const full = useRef(evaluation);
  full.current = evaluation;
  const open = useCallback(
    (groupId: string) => {
      const inside = scopeDocument(base.getState().doc, [...path, groupId]);
      if (inside) setPath([...path, groupId]);
    },
    [base, path],
  );
  const goTo = useCallback((depth: number) => setPath((p) => p.slice(0, depth)), []);
  const names = path.map((_, i) => {
    const level = scopeDocument(doc, path.slice(0, i));
    const node = level?.nodes.find((n) => n.id === path[i]);
    return node?.label ?? 'Group';
  });
  const body =
    path.length > 0
      ? scopeDocument(doc, path.slice(0, -1))?.nodes.find((n) => n.id === path.at(-1))?.group
      : undefined;
  const list = (label: string, ps: readonly { name: string; label?: string }[]) =>
    ps.length > 0 ? [`${label}: ${ps.map((p) => p.label ?? p.name).join(', ')}`] : [];
  const ports = body ? [...list('inputs', body.inputs), ...list('outputs', body.outputs)].join(' · ') : '';
  return {
    path,
    names,
    ports,
    base,
    store,
    evaluation: scoped,
    extraDiagnostics,
    full,
    frameKey,
    open,
    goTo,
  };
}

/** "Graph › Group › Inner group": each crumb but the last goes back out to its level. */
export function GroupBreadcrumb({ scope }: { scope: GroupScope }) {
  if (scope.path.length === 0) return null;
  const crumbs = ['Graph', ...scope.names];
  const keys = ['(top)', ...scope.path];
  return (
    <nav className="kf-breadcrumb" aria-label="Open group">
      {crumbs.map((name, depth) => {
        const current = depth === crumbs.length - 1;
        return (
          <span key={keys[depth]}>
            {depth > 0 && <span className="kf-breadcrumb__sep">›</span>}
            <button
              type="button"
              className="kf-button"
              aria-current={current ? 'location' : undefined}
              disabled={current}
              title={current ? 'The group you are editing' : 'Back out to this level'}
              onClick={() => scope.goTo(depth)}
            >
              {name}
            </button>
          </span>
        );
      })}
      {scope.ports && <span className="kf-breadcrumb__ports">{scope.ports}</span>}
    </nav>
  );
}
