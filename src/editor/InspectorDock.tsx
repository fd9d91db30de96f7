/**
 * The inspector docked beside the graph canvas (never over it, so it cannot cover the node it
 * inspects): a resize handle on its left edge (drag, or ←/→ when focused; the width is
 * remembered), and Esc inside it closes it. Shows the selected node, or a hint when none is —
 * with a button that opens the render node (render-node-suggestion.ts), the keyboard then in it.
 */
import { useEffect, useRef } from 'react';
import type { Diagnostic } from '../../nodes/core/diagnostics.ts';
import type { GraphNode } from '../../nodes/graph/document.ts';
import type { NodeEvaluation } from '../../nodes/graph/evaluate.ts';
import { Inspector } from './Inspector.tsx';
import { clampPanelWidth, PANEL_WIDTH, usePanelWidth } from './panel-width.ts';
import type { NodeSuggestion } from './render-node-suggestion.ts';
import { isTyping } from './typing.ts';

interface Props {
  readonly node: GraphNode | undefined;
  readonly connected: ReadonlySet<string>;
  readonly evaluation: NodeEvaluation | undefined;
  readonly diagnostics: readonly Diagnostic[];
  /** The phone's Inspector tab: the panel fills the pane (its CSS), so no width of its own. */
  readonly fill?: boolean;
  onLabel(label: string): void;
  onMute(muted: boolean): void;
  /** Closes the panel; `fromKeyboard` when by Esc (then focus should go somewhere sensible). */
  onClose(fromKeyboard?: boolean): void;
  /** The node the empty panel offers to inspect (the render node), and how it selects it. */
  readonly suggested?: NodeSuggestion;
  onInspect?(nodeId: string): void;
}

/** The width of the area the dock shares with the canvas (its parent), 0 before layout. */
const areaWidth = (el: Element | null) => el?.parentElement?.clientWidth ?? 0;

export function InspectorDock({ node, fill = false, onClose, suggested, onInspect, ...inspector }: Props) {
  const [width, setWidth] = usePanelWidth('kleinflow.inspector.width');
  // The suggestion's button goes away as its node opens: the keyboard follows into the panel.
  const dock = useRef<HTMLDivElement>(null);
  const focusOpened = useRef(false);
  useEffect(() => {
    if (!node || !focusOpened.current) return;
    focusOpened.current = false;
    dock.current?.querySelector<HTMLElement>('.kf-inspector')?.focus();
  }, [node]);
  return (
    // biome-ignore lint/a11y/noStaticElementInteractions: Esc from anywhere inside the panel closes it (its controls are the interactive parts)
    <div
      ref={dock}
      className="kf-inspector-dock"
      style={fill ? undefined : { width }}
      onKeyDown={(e) => {
        if (e.key !== 'Escape' || isTyping(e.target)) return;
        e.preventDefault();
        onClose(true);
      }}
    >
      {/* biome-ignore lint/a11y/useSemanticElements: a draggable splitter, not a rule */}
      <div
        className="kf-inspector-dock__handle"
        role="separator"
        aria-orientation="vertical"
        aria-label="Resize inspector"
        aria-valuenow={width}
        aria-valuemin={PANEL_WIDTH.min}
        aria-valuemax={PANEL_WIDTH.max}
        tabIndex={0}
        onPointerDown={(e) => {
          e.currentTarget.setPointerCapture(e.pointerId);
        }}
        onPointerMove={(e) => {
          if (!e.currentTarget.hasPointerCapture(e.pointerId)) return;
          const dock = e.currentTarget.parentElement!;
          const right = dock.getBoundingClientRect().right;
          setWidth(clampPanelWidth(right - e.clientX, areaWidth(dock)));
        }}
        onKeyDown={(e) => {
          const step = e.shiftKey ? 4 * PANEL_WIDTH.step : PANEL_WIDTH.step;
          // The handle is the panel's left edge: ← moves it left, making the panel wider.
          const by = { ArrowLeft: step, ArrowRight: -step, Home: -Infinity, End: Infinity }[e.key];
          if (by === undefined) return;
          e.preventDefault();
          const next = Number.isFinite(by) ? width + by : by > 0 ? PANEL_WIDTH.max : PANEL_WIDTH.min;
          setWidth(clampPanelWidth(next, areaWidth(e.currentTarget.parentElement)));
        }}
      />
      {node ? (
        <Inspector node={node} {...inspector} onClose={() => onClose()} />
      ) : (
        <aside className="kf-inspector kf-inspector--empty" aria-label="Inspector" tabIndex={-1}>
          <header className="kf-inspector__header">
            <h2>Inspector</h2>
            <button
              type="button"
              className="kf-icon-button kf-inspector__close"
              aria-label="Close inspector"
              onClick={() => onClose()}
            >
              ×
            </button>
          </header>
          <p className="kf-inspector__hint-empty">Select one node to inspect it.</p>
          {suggested && onInspect && (
            <p className="kf-inspector__hint-empty">
              <button
                type="button"
                className="kf-button"
                title="The node that makes the picture: its render settings"
                onClick={() => {
                  focusOpened.current = true;
                  onInspect(suggested.id);
                }}
              >
                Inspect {suggested.title}
              </button>
            </p>
          )}
        </aside>
      )}
    </div>
  );
}
