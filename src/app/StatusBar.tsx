/** The status line: diagnostics (click for the list), render progress and autosave state. */
import { type CSSProperties, useEffect, useLayoutEffect, useRef, useState } from 'react';
import type { Diagnostic, DiagnosticFix } from '../../nodes/core/diagnostics.ts';
import { FixButton } from '../editor/FixButton.tsx';
import type { RenderInfo } from './RenderPane.tsx';
import { useNarrow } from './use-narrow.ts';

interface Props {
  readonly diagnostics: readonly Diagnostic[];
  readonly render: RenderInfo | null;
  readonly nodes: number;
  readonly edges: number;
  readonly saveState: string;
  /**
   * The node's name as people see it, for the list's entries: its title, told apart by its order
   * where several nodes share one (nodes/graph/node-names.ts); ids are internal.
   */
  titleOf(id: string): string;
  /** Selects the node and brings it into view in the graph. */
  onSelectNode(id: string): void;
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

/** A phone's status line has no room for "Saved in this browser": "Saved" says it (title: all). */
function shortSaveState(state: string): string {
  return state === 'Saved in this browser' ? 'Saved' : state;
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

/**
 * Where the open list goes: fixed above the status line, inside the window. The status line clips
 * what overflows it (a long line must not widen the app), so the list cannot hang from it.
 */
function useListPlace(open: boolean) {
  const bar = useRef<HTMLElement>(null);
  const [place, setPlace] = useState<CSSProperties>({});
  // Before paint: the list never shows (nor is seen by anyone) at an unplaced spot.
  useLayoutEffect(() => {
    if (!open) return undefined;
    const measure = () => {
      const top = bar.current?.getBoundingClientRect().top ?? window.innerHeight;
      setPlace({ bottom: window.innerHeight - top + 4, maxHeight: Math.max(120, top - 16) });
    };
    measure();
    window.addEventListener('resize', measure);
    return () => window.removeEventListener('resize', measure);
  }, [open]);
  return { bar, place };
}

export function StatusBar(props: Props) {
  const { diagnostics, render, nodes, edges, saveState, titleOf, onSelectNode, onFix } = props;
  const [open, setOpen] = useState(false);
  const { bar, place } = useListPlace(open);
  const narrow = useNarrow();
  const errors = diagnostics.filter((d) => d.severity === 'error').length;
  const warnings = diagnostics.filter((d) => d.severity === 'warning').length;
  const announcement = useRenderAnnouncement(render);
  return (
    <footer className="kf-status" ref={bar}>
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
      <span className="kf-status__item kf-status__muted" data-testid="save-state" title={saveState}>
        {narrow ? shortSaveState(saveState) : saveState}
      </span>
      {open && diagnostics.length > 0 && (
        <ul className="kf-status__list" aria-label="Diagnostics" style={place}>
          {diagnostics.map((d, i) => (
            // biome-ignore lint/suspicious/noArrayIndexKey: diagnostics may repeat; their order is stable
            <li key={i} className={`kf-diag kf-diag--${d.severity}`}>
              <code>{d.code}</code>{' '}
              {d.nodeId ? (
                <button type="button" className="kf-link" onClick={() => onSelectNode(d.nodeId!)}>
                  {titleOf(d.nodeId)}
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
