/**
 * The first-visit card: open an example, build a kaleidoscope step by step, or start from an
 * empty canvas. Any choice (or ×) dismisses it for good in this browser.
 */
import { useEffect } from 'react';
import type { Example } from '../examples.ts';
import { useNarrow } from '../use-narrow.ts';

interface Props {
  readonly examples: readonly Example[];
  onExample(example: Example): void;
  onWalkthrough(): void;
  onEmpty(): void;
  onDismiss(): void;
}

const FIRST_EXAMPLES = ['hyperbolic-237', 'kaleidoscope-333', 'apollonian-gasket', 'loxodromic-spiral'];

export function WelcomeCard({ examples, onExample, onWalkthrough, onEmpty, onDismiss }: Props) {
  // Escape dismisses it like every other popup.
  useEffect(() => {
    const onKey = (e: KeyboardEvent) => e.key === 'Escape' && onDismiss();
    window.addEventListener('keydown', onKey);
    return () => window.removeEventListener('keydown', onKey);
  }, [onDismiss]);
  // A phone shows one pane at a time: the picture is a tab there, not the right-hand side.
  const narrow = useNarrow();
  const firsts = FIRST_EXAMPLES.flatMap((id) => examples.filter((e) => e.id === id));
  return (
    <section className="kf-welcome" aria-label="Welcome to Kleinflow">
      <header className="kf-welcome__header">
        <h2>Welcome to Kleinflow</h2>
        <button type="button" className="kf-icon-button" aria-label="Close welcome" onClick={onDismiss}>
          ×
        </button>
      </header>
      <p className="kf-welcome__lead">
        Wire mirrors into a Render node and the picture {narrow ? 'in the Picture tab' : 'on the right'}{' '}
        follows every change. How would you like to start?
      </p>
      <div className="kf-welcome__choices">
        <button type="button" className="kf-button kf-button--primary" onClick={onWalkthrough}>
          Build a kaleidoscope step by step
        </button>
        <button type="button" className="kf-button" onClick={onEmpty}>
          Empty canvas
        </button>
      </div>
      <p className="kf-welcome__label">Or open an example:</p>
      <ul className="kf-welcome__examples">
        {firsts.map((e) => (
          <li key={e.id}>
            <button type="button" className="kf-button" title={e.description} onClick={() => onExample(e)}>
              {e.title}
            </button>
          </li>
        ))}
      </ul>
    </section>
  );
}
