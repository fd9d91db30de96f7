/** The classroom step control: ◀ ▶ (and the arrow keys) through the construction, one node at a time. */
import type { ConstructionStep } from './construction-steps.ts';

interface Props {
  readonly steps: readonly ConstructionStep[];
  /** How many steps are built (0 … steps.length). */
  readonly count: number;
  onCount(count: number): void;
}

/** A bar-and-triangle "to the end" icon (SVG: the ⏮ ⏭ glyphs are missing from many fonts). */
function EndIcon({ flip = false }: { flip?: boolean }) {
  return (
    <svg
      viewBox="0 0 12 12"
      width="12"
      height="12"
      aria-hidden="true"
      style={flip ? { transform: 'scaleX(-1)' } : undefined}
    >
      <path d="M2 1.5 L8 6 L2 10.5 Z" fill="currentColor" />
      <rect x="8.5" y="1.5" width="1.6" height="9" fill="currentColor" />
    </svg>
  );
}

export function StepBar({ steps, count, onCount }: Props) {
  const current = count > 0 ? steps[count - 1] : undefined;
  const go = (n: number) => onCount(Math.min(steps.length, Math.max(0, n)));
  return (
    <nav className="kf-steps" aria-label="Construction steps">
      <button
        type="button"
        className="kf-button kf-button--icon"
        aria-label="First step"
        title="Start (Home)"
        onClick={() => go(0)}
        disabled={count === 0}
      >
        <EndIcon flip />
      </button>
      <button
        type="button"
        className="kf-button kf-button--icon"
        aria-label="Previous step"
        title="Previous step (←)"
        onClick={() => go(count - 1)}
        disabled={count === 0}
      >
        ◀
      </button>
      <div className="kf-steps__now" aria-live="polite" data-testid="step-now">
        <span className="kf-steps__count">
          Step {count} / {steps.length}
        </span>
        {current ? (
          <>
            <strong className="kf-steps__label">{current.label}</strong>
            {current.label !== current.typeLabel && (
              <span className="kf-steps__type">{current.typeLabel}</span>
            )}
          </>
        ) : (
          <span className="kf-steps__type">Nothing built yet: press ▶ or →</span>
        )}
      </div>
      <button
        type="button"
        className="kf-button kf-button--icon"
        aria-label="Next step"
        title="Next step (→)"
        onClick={() => go(count + 1)}
        disabled={count === steps.length}
      >
        ▶
      </button>
      <button
        type="button"
        className="kf-button kf-button--icon"
        aria-label="Last step"
        title="Whole construction (End)"
        onClick={() => go(steps.length)}
        disabled={count === steps.length}
      >
        <EndIcon />
      </button>
    </nav>
  );
}
