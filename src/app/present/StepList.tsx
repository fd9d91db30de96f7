/** Every step of the construction at a glance: click one to build up to it; notes are marked ✎. */
import type { ConstructionStep } from './construction-steps.ts';

interface Props {
  readonly steps: readonly ConstructionStep[];
  readonly count: number;
  readonly notes: Readonly<Record<string, string>>;
  onCount(count: number): void;
}

export function StepList({ steps, count, notes, onCount }: Props) {
  return (
    <nav className="kf-step-list" aria-label="Step list">
      <ol>
        {steps.map((s, i) => (
          <li key={s.nodeId}>
            <button
              type="button"
              className={`kf-step-list__item${i < count ? ' kf-step-list__item--built' : ''}`}
              aria-current={i + 1 === count ? 'step' : undefined}
              onClick={() => onCount(i + 1)}
            >
              <span className="kf-step-list__n">{i + 1}</span>
              <span className="kf-step-list__label">{s.label}</span>
              {notes[s.nodeId]?.trim() && (
                <span className="kf-step-list__note" title="This step has a note">
                  ✎
                </span>
              )}
            </button>
          </li>
        ))}
      </ol>
    </nav>
  );
}
