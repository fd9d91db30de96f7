/** The status line: diagnostics (click for the list), render progress and autosave state. */
import { useEffect, useState } from 'react';
import type { Diagnostic, DiagnosticFix } from '../../nodes/core/diagnostics.ts';
import { FixButton } from '../editor/FixButton.tsx';
import type { RenderInfo } from './RenderPane.tsx';

interface Props {
  readonly diagnostics: readonly Diagnostic[];
  readonly render: RenderInfo | null;
  readonly nodes: number;
  readonly edges: number;
  readonly saveState: string;
  onSelectNode(id: string): void;
  /** The node's title as people see it (ids are internal); the id when not given. */
  nodeName?(id: string): string;
  /** Runs a diagnostic's one-click fix. */
  onFix(fix: DiagnosticFix): void;
}

/** The render progress line (see the README's "The 3D view"). */
function progressText(render: RenderInfo): string {
  const percent = (f: number) => `${Math.round(f * 100)} %`;
  if (render.band !== undefined && render.samples === 0) return `Full size: ${percent(render.band)} …`;
  if (render.scale !== undefined && render.scale < 1) return `Preview at ${percent(render.scale)} resolution`;
  const done = render.samples >= render.target;
  const text = `${done ? 'Rendered' : 'Rendering'} ${render.samples}/${render.target} samples`;
  return render.band === undefined ? text : `${text} (next: ${percent(render.band)})`;
}

/**
 * What a screen reader hears: only that a slow full-size picture is being drawn and that it is
 * done, never each band's percentage or each sample (the progress line changes every frame).
 */
function useRenderAnnouncement(render: RenderInfo | null): string {
  const [said, setSaid] = useState('');
  const banding = render?.band !== undefined && render.samples === 0;
  const full = render !== null && render.band === undefined && (render.scale ?? 1) === 1;
  useEffect(() => {
    if (banding) setSaid('Drawing the picture at full size…');
    else if (full) setSaid((s) => (s === '' ? s : 'The full-size picture is drawn.'));
  }, [banding, full]);
  return said;
}

export function StatusBar({
  diagnostics,
  render,
  nodes,
  edges,
  saveState,
  onSelectNode,
  nodeName,
  onFix,
}: Props) {
  const [open, setOpen] = useState(false);
  const errors = diagnostics.filter((d) => d.severity === 'error').length;
  const warnings = diagnostics.filter((d) => d.severity === 'warning').length;
  const announcement = useRenderAnnouncement(render);
  return (
    <footer className="kf-status">
      <button
        type="button"
        className={`kf-status__diag${errors ? ' kf-status__diag--error' : warnings ? ' kf-status__diag--warning' : ''}`}
        onClick={() => setOpen(!open)}
        aria-expanded={open}
        data-testid="diagnostics-count"
      >
        {errors === 0 && warnings === 0
          ? '✓ No problems'
          : `${errors} error${errors === 1 ? '' : 's'} · ${warnings} warning${warnings === 1 ? '' : 's'}`}
      </button>
      <span className="kf-status__sep" />
      <span data-testid="render-progress" className="kf-status__item">
        {render ? (
          <>
            {progressText(render)}
            {render.ms > 0 && <span className="kf-status__muted"> · {render.ms.toFixed(0)} ms/frame</span>}
          </>
        ) : (
          'Renderer starting…'
        )}
      </span>
      <span className="kf-visually-hidden" role="status" data-testid="render-announcement">
        {announcement}
      </span>
      <span className="kf-status__spacer" />
      <span className="kf-status__item kf-status__muted">
        {nodes} nodes · {edges} wires
      </span>
      <span className="kf-status__sep" />
      <span className="kf-status__item kf-status__muted" data-testid="save-state">
        {saveState}
      </span>
      {open && diagnostics.length > 0 && (
        <ul className="kf-status__list" aria-label="Diagnostics">
          {diagnostics.map((d, i) => (
            // biome-ignore lint/suspicious/noArrayIndexKey: diagnostics may repeat; their order is stable
            <li key={i} className={`kf-diag kf-diag--${d.severity}`}>
              <code>{d.code}</code>{' '}
              {d.nodeId ? (
                <button type="button" className="kf-link" onClick={() => onSelectNode(d.nodeId!)}>
                  {nodeName ? nodeName(d.nodeId) : d.nodeId}
                </button>
              ) : (
                d.path && <code>{d.path}</code>
              )}{' '}
              {d.message}
              {d.fix && (
                <>
                  {' '}
                  <FixButton fix={d.fix} onFix={onFix} />
                </>
              )}
            </li>
          ))}
        </ul>
      )}
    </footer>
  );
}
