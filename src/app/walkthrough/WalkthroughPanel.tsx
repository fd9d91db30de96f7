/**
 * The guided walkthrough as a small panel over the graph: every step with a tick once the document
 * shows it done, the "how" of the first open step, and what is still missing.
 */
import type { GraphDoc } from '../../../nodes/graph/document.ts';
import type { Evaluation } from '../../../nodes/graph/evaluate.ts';
import { useStore } from '../../state/use-store.ts';
import { WALKTHROUGH, walkthroughStatus } from './steps.ts';

interface Props {
  readonly doc: GraphDoc;
  readonly evaluation: Evaluation;
  onClose(): void;
}

export function WalkthroughPanel({ doc, evaluation, onClose }: Props) {
  const store = useStore();
  const status = walkthroughStatus(doc, evaluation);
  const current = status.findIndex((s) => !s.done);
  return (
    <section className="kf-walkthrough" aria-label="Walkthrough">
      <header className="kf-walkthrough__header">
        <h2>Build the *333 kaleidoscope</h2>
        <button type="button" className="kf-icon-button" aria-label="Close walkthrough" onClick={onClose}>
          ×
        </button>
      </header>
      <ol className="kf-walkthrough__steps">
        {WALKTHROUGH.map((step, i) => {
          const s = status[i];
          const state = s.done ? 'done' : i === current ? 'current' : 'later';
          return (
            <li
              key={step.id}
              className={`kf-walkthrough__step kf-walkthrough__step--${state}`}
              data-done={s.done}
            >
              <span className="kf-walkthrough__mark" aria-hidden>
                {s.done ? '✓' : i + 1}
              </span>
              <div>
                <strong>{step.title}</strong>
                {s.done && <span className="kf-visually-hidden"> (done)</span>}
                {i === current && <p className="kf-walkthrough__how">{step.how}</p>}
                {i === current && s.todo && <p className="kf-walkthrough__todo">{s.todo}</p>}
                {i === current && s.flip && s.flip.length > 0 && (
                  <button
                    type="button"
                    className="kf-button"
                    onClick={() =>
                      store.dispatch(
                        {
                          type: 'set-params',
                          patches: s.flip!.map((nodeId) => ({ nodeId, params: { flip: true } })),
                        },
                        'flip mirror',
                      )
                    }
                  >
                    Flip {s.flip.length === 1 ? 'it' : 'them'}
                  </button>
                )}
              </div>
            </li>
          );
        })}
      </ol>
      {current === -1 && (
        <p className="kf-walkthrough__done" role="status">
          Done! Three mirrors at π/3 angles tile the plane. Drag a corner in the picture and watch the tiling
          follow.
        </p>
      )}
    </section>
  );
}
