/**
 * The classroom view: the live render full-window, the title and description, the step list and a
 * step control that builds the construction node by node from step 1 (the picture appears once
 * the Render node is reached), and the note the author wrote for the current step. Read-only: the
 * render shows no draggable handles and the graph is not on screen, so nothing can change it.
 * Opened from the editor (`onExit` given) the author can also edit the text and copy the class
 * links; Esc goes back. Opened from a link (`?mode=present`) it is for the audience only.
 */
import { useCallback, useEffect, useMemo, useState } from 'react';
import type { NodePath } from '../../../nodes/graph/flatten.ts';
import { registry } from '../../../nodes/types/index.ts';
import { isTyping } from '../../editor/typing.ts';
import { createEvaluator } from '../../state/evaluation.ts';
import { useEditorState } from '../../state/use-store.ts';
import { RenderPane } from '../RenderPane.tsx';
import { useNarrow } from '../use-narrow.ts';
import { constructionSteps, evaluationToDepth, evaluationUpTo, renderReached } from './construction-steps.ts';
import { GrowthBar, nextDepth } from './GrowthBar.tsx';
import { Markdown } from './markdown.tsx';
import { PresentEditor } from './PresentEditor.tsx';
import { StepBar } from './StepBar.tsx';
import { StepList } from './StepList.tsx';

const noop = () => {};
const NO_NOTES: Readonly<Record<string, string>> = {};

interface Props {
  /** Leaves the presentation (back to the editor); without it the view is the audience's. */
  onExit?(): void;
  /** Where "Edit in Kleinflow" goes, for the audience's view. */
  editorHref?: string;
}

export function Presentation({ onExit, editorHref }: Props) {
  const doc = useEditorState((s) => s.doc);
  const time = useEditorState((s) => s.time);
  const narrow = useNarrow();
  const evaluate = useMemo(() => createEvaluator(registry), []);
  const evaluation = useMemo(() => evaluate(doc, time), [evaluate, doc, time]);
  const steps = useMemo(() => constructionSteps(evaluation), [evaluation]);
  const [count, setCount] = useState(1);
  const [hovered, setHovered] = useState<NodePath | null>(null);
  const [listOpen, setListOpen] = useState(!narrow);
  // On a phone the list covers the picture: closed by default, and closed again once a step is picked.
  useEffect(() => setListOpen(!narrow), [narrow]);
  const [editing, setEditing] = useState(false);
  const [headOpen, setHeadOpen] = useState(false);
  const built = Math.min(count, steps.length);
  const [depth, setDepth] = useState<number | null>(null);
  const pictured = built >= steps.length || renderReached(evaluation, steps, built);
  const shown = useMemo(
    () => evaluationToDepth(evaluationUpTo(evaluation, steps, built), pictured ? depth : null),
    [evaluation, steps, built, pictured, depth],
  );

  const step = useCallback((n: number) => setCount(Math.min(steps.length, Math.max(0, n))), [steps.length]);
  useEffect(() => {
    const onKey = (e: KeyboardEvent) => {
      if (isTyping(e.target) || e.ctrlKey || e.metaKey || e.altKey) return;
      if (e.key === 'ArrowRight' || e.key === 'PageDown') step(built + 1);
      else if (e.key === 'ArrowLeft' || e.key === 'PageUp') step(built - 1);
      else if (e.key === 'Home') step(0);
      else if (e.key === 'End') step(steps.length);
      else if (e.key === 'Escape' && onExit) onExit();
      else if ((e.key === 'g' || e.key === 'G') && pictured) setDepth(nextDepth);
      else return;
      e.preventDefault();
    };
    window.addEventListener('keydown', onKey);
    return () => window.removeEventListener('keydown', onKey);
  }, [step, built, steps.length, onExit, pictured]);

  const current = built > 0 ? steps[built - 1] : undefined;
  const notes = doc.meta.stepNotes ?? NO_NOTES;
  const note = current ? notes[current.nodeId]?.trim() : undefined;
  const title = doc.meta.title?.trim() || 'Untitled construction';
  const classes = [
    'kf-present',
    'kf-present--present',
    pictured ? '' : 'kf-present--construction',
    editing ? 'kf-present--editing' : '',
    listOpen ? 'kf-present--listing' : '',
  ];
  return (
    <div className={classes.filter(Boolean).join(' ')} data-testid="present-mode">
      <div className="kf-present__stage">
        <RenderPane
          evaluation={shown}
          hovered={hovered}
          onHover={setHovered}
          onDiagnostics={noop}
          onFrame={noop}
          onViewport={noop}
          readOnly
        />
        <header className={`kf-present__head${headOpen ? ' kf-present__head--open' : ''}`}>
          <h1 className="kf-present__title">{title}</h1>
          {doc.meta.description?.trim() && (
            <>
              <Markdown className="kf-present__description" text={doc.meta.description} />
              {narrow && (
                <button
                  type="button"
                  className="kf-present__more"
                  aria-expanded={headOpen}
                  onClick={() => setHeadOpen(!headOpen)}
                >
                  {headOpen ? 'Less' : 'More'}
                </button>
              )}
            </>
          )}
        </header>
        <div className="kf-present__tools" role="toolbar" aria-label="Presentation">
          <button
            type="button"
            className={`kf-button${listOpen ? ' kf-button--active' : ''}`}
            aria-pressed={listOpen}
            onClick={() => setListOpen(!listOpen)}
          >
            Steps
          </button>
          {onExit ? (
            <>
              <button
                type="button"
                className={`kf-button${editing ? ' kf-button--active' : ''}`}
                aria-pressed={editing}
                title="Write the title, description and a note for each step"
                onClick={() => setEditing(!editing)}
              >
                Edit text
              </button>
              <button type="button" className="kf-button" title="Back to the editor (Esc)" onClick={onExit}>
                Leave
              </button>
            </>
          ) : (
            <a className="kf-button" href={editorHref} title="Open this graph in the editor">
              Edit in Kleinflow
            </a>
          )}
        </div>
        {listOpen && steps.length > 0 && (
          <StepList
            steps={steps}
            count={built}
            notes={notes}
            onCount={(n) => {
              step(n);
              if (narrow) setListOpen(false);
            }}
          />
        )}
        <div className="kf-present__foot">
          {note && (
            <section className="kf-present__note" aria-label="Step note">
              <Markdown text={note} />
            </section>
          )}
          {pictured && <GrowthBar depth={depth} onDepth={setDepth} />}
          {steps.length > 0 && <StepBar steps={steps} count={built} onCount={step} />}
        </div>
      </div>
      {editing && onExit && <PresentEditor step={current} number={built} />}
    </div>
  );
}
