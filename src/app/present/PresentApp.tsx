/**
 * The link faces of Kleinflow: `?mode=present` (the audience's read-only presentation, see
 * Presentation.tsx) and `?mode=embed` (only the render and a small "Open in Kleinflow" link, for
 * iframes). A `#g=` link in the address is loaded and kept (an iframe reload must show the same
 * graph); nothing here is autosaved.
 */
import { useEffect, useMemo, useState } from 'react';
import type { GraphDoc } from '../../../nodes/graph/document.ts';
import type { NodePath } from '../../../nodes/graph/flatten.ts';
import { registry } from '../../../nodes/types/index.ts';
import { createEvaluator } from '../../state/evaluation.ts';
import { useEditorState, useStore } from '../../state/use-store.ts';
import { OpenReportPanel } from '../io/OpenReportPanel.tsx';
import type { OpenReport } from '../io/open-report.ts';
import { readStartupLink, shareLinkFor } from '../io/share-link.ts';
import { RenderPane } from '../RenderPane.tsx';
import { Presentation } from './Presentation.tsx';

const noop = () => {};

/** The editor's address for `doc` (with its share link when it fits). */
function editorLink(doc: GraphDoc): string {
  const link = shareLinkFor(doc, window.location);
  return link.ok ? link.url : `${window.location.origin}${window.location.pathname}`;
}

function Embed() {
  const doc = useEditorState((s) => s.doc);
  const time = useEditorState((s) => s.time);
  const evaluate = useMemo(() => createEvaluator(registry), []);
  const evaluation = useMemo(() => evaluate(doc, time), [evaluate, doc, time]);
  const [hovered, setHovered] = useState<NodePath | null>(null);
  return (
    <div className="kf-present kf-present--embed" data-testid="embed-mode">
      <RenderPane
        evaluation={evaluation}
        hovered={hovered}
        onHover={setHovered}
        onDiagnostics={noop}
        onFrame={noop}
        onViewport={noop}
        readOnly
      />
      <a className="kf-embed__link" href={editorLink(doc)} target="_blank" rel="noopener noreferrer">
        Open in Kleinflow
      </a>
    </div>
  );
}

export function PresentApp({ mode }: { mode: 'present' | 'embed' }) {
  const store = useStore();
  const doc = useEditorState((s) => s.doc);
  const [report, setReport] = useState<OpenReport | null>(null);

  // The link is the document: one typed into the address bar later (a hash change) is shown too,
  // still read-only — this page never edits, so nobody's graph is replaced.
  useEffect(() => {
    const apply = (shown: string) => {
      const link = readStartupLink(window.location.hash);
      if (link.kind === 'ok') store.dispatch({ type: 'load-document', doc: link.doc }, 'open shared link');
      else if (link.kind === 'broken')
        setReport({
          kind: 'error',
          title: `The shared link could not be opened; ${shown}.`,
          items: [{ path: '(link)', text: link.message, code: 'KF501' }],
        });
    };
    apply('showing the graph saved in this browser');
    const onHash = () => apply('the picture is unchanged');
    window.addEventListener('hashchange', onHash);
    return () => window.removeEventListener('hashchange', onHash);
  }, [store]);

  return (
    <>
      {mode === 'embed' ? <Embed /> : <Presentation editorHref={editorLink(doc)} />}
      {report && <OpenReportPanel report={report} onDismiss={() => setReport(null)} />}
    </>
  );
}
