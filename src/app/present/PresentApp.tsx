/**
 * The classroom and iframe faces of Kleinflow: the live render full-window with its draggable
 * handles and labels, no graph. `present` adds the title, description and a step control that
 * builds the construction node by node (the picture appears once the Render node is reached);
 * `embed` shows only the render and a small "Open in Kleinflow" link. A `#g=` link in the address
 * is loaded and kept (an iframe reload must show the same graph); nothing here is autosaved.
 */
import { useCallback, useEffect, useMemo, useState } from 'react';
import type { GraphDoc } from '../../../nodes/graph/document.ts';
import { registry } from '../../../nodes/types/index.ts';
import { createEvaluator } from '../../state/evaluation.ts';
import { useEditorState, useStore } from '../../state/use-store.ts';
import { OpenReportPanel } from '../io/OpenReportPanel.tsx';
import type { OpenReport } from '../io/open-report.ts';
import { readStartupLink, shareLinkFor } from '../io/share-link.ts';
import { RenderPane } from '../RenderPane.tsx';
import { constructionSteps, evaluationUpTo, renderReached } from './construction-steps.ts';
import { StepBar } from './StepBar.tsx';

const noop = () => {};

/** The editor's address for `doc` (with its share link when it fits). */
function editorLink(doc: GraphDoc): string {
  const link = shareLinkFor(doc, window.location);
  return link.ok ? link.url : `${window.location.origin}${window.location.pathname}`;
}

export function PresentApp({ mode }: { mode: 'present' | 'embed' }) {
  const store = useStore();
  const doc = useEditorState((s) => s.doc);
  const time = useEditorState((s) => s.time);
  const evaluate = useMemo(() => createEvaluator(registry), []);
  const evaluation = useMemo(() => evaluate(doc, time), [evaluate, doc, time]);
  const steps = useMemo(() => constructionSteps(evaluation), [evaluation]);
  const [count, setCount] = useState<number | null>(null); // null: the whole construction
  const [hovered, setHovered] = useState<string | null>(null);
  const [report, setReport] = useState<OpenReport | null>(null);
  const built = mode === 'embed' || count === null ? steps.length : Math.min(count, steps.length);
  const shown = useMemo(() => evaluationUpTo(evaluation, steps, built), [evaluation, steps, built]);
  const pictured = built >= steps.length || renderReached(evaluation, steps, built);

  useEffect(() => {
    const link = readStartupLink(window.location.hash);
    if (link.kind === 'ok') store.dispatch({ type: 'load-document', doc: link.doc }, 'open shared link');
    else if (link.kind === 'broken')
      setReport({
        kind: 'error',
        title: 'The shared link could not be opened; showing the graph saved in this browser.',
        items: [{ path: '(link)', text: link.message, code: 'KF501' }],
      });
  }, [store]);

  const step = useCallback((n: number) => setCount(Math.min(steps.length, Math.max(0, n))), [steps.length]);
  useEffect(() => {
    if (mode !== 'present') return;
    const onKey = (e: KeyboardEvent) => {
      if (e.key === 'ArrowRight' || e.key === 'PageDown') step(built + 1);
      else if (e.key === 'ArrowLeft' || e.key === 'PageUp') step(built - 1);
      else if (e.key === 'Home') step(0);
      else if (e.key === 'End') step(steps.length);
      else return;
      e.preventDefault();
    };
    window.addEventListener('keydown', onKey);
    return () => window.removeEventListener('keydown', onKey);
  }, [mode, step, built, steps.length]);

  const title = doc.meta.title?.trim() || 'Untitled construction';
  return (
    <div
      className={`kf-present kf-present--${mode}${pictured ? '' : ' kf-present--construction'}`}
      data-testid={`${mode}-mode`}
    >
      <RenderPane
        evaluation={shown}
        hoveredNodeId={hovered}
        onHoverNode={setHovered}
        onDiagnostics={noop}
        onFrame={noop}
        onViewport={noop}
      />
      {mode === 'present' ? (
        <>
          <header className="kf-present__head">
            <h1 className="kf-present__title">{title}</h1>
            {doc.meta.description && <p className="kf-present__description">{doc.meta.description}</p>}
          </header>
          <a
            className="kf-present__edit kf-button"
            href={editorLink(doc)}
            title="Open this graph in the editor"
          >
            Edit in Kleinflow
          </a>
          {steps.length > 0 && <StepBar steps={steps} count={built} onCount={step} />}
        </>
      ) : (
        <a className="kf-embed__link" href={editorLink(doc)} target="_blank" rel="noopener noreferrer">
          Open in Kleinflow
        </a>
      )}
      {report && <OpenReportPanel report={report} onDismiss={() => setReport(null)} />}
    </div>
  );
}
