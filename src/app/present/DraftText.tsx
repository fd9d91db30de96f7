/**
 * A text field that edits document text as one undo step: typing stays local, leaving the field
 * (or the field disappearing, e.g. Esc out of the presentation) commits it. `maxLength` is the
 * document schema's limit, so a saved file always loads again.
 */
import { useEffect, useId, useRef, useState } from 'react';

interface Props {
  readonly label: string;
  readonly value: string;
  readonly maxLength: number;
  readonly multiline?: boolean;
  readonly placeholder?: string;
  onCommit(value: string): void;
}

export function DraftText({ label, value, maxLength, multiline = false, placeholder, onCommit }: Props) {
  const [draft, setDraft] = useState(value);
  useEffect(() => setDraft(value), [value]);
  const pending = useRef({ draft, value, onCommit });
  pending.current = { draft, value, onCommit };
  useEffect(
    () => () => {
      const p = pending.current;
      if (p.draft !== p.value) p.onCommit(p.draft);
    },
    [],
  );
  const fieldId = useId();
  const commit = () => draft !== value && onCommit(draft);
  const common = {
    id: fieldId,
    'aria-label': label,
    value: draft,
    maxLength,
    placeholder,
    className: 'kf-present-edit__field',
    onBlur: commit,
  };
  return (
    <label className="kf-present-edit__label" htmlFor={fieldId}>
      <span>
        {label}
        {draft.length > maxLength * 0.8 && (
          <span className="kf-present-edit__count">
            {' '}
            {draft.length} / {maxLength}
          </span>
        )}
      </span>
      {multiline ? (
        <textarea
          {...common}
          rows={4}
          onChange={(e) => setDraft(e.target.value)}
          onKeyDown={(e) => e.key === 'Escape' && e.currentTarget.blur()}
        />
      ) : (
        <input
          {...common}
          onChange={(e) => setDraft(e.target.value)}
          onKeyDown={(e) => (e.key === 'Enter' || e.key === 'Escape') && e.currentTarget.blur()}
        />
      )}
    </label>
  );
}
