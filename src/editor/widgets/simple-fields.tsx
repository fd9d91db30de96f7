/** Toggles, enum selects and colour pickers: edits that end at once (each is one undo step). */
import { useEffect, useId, useRef } from 'react';
import type { OnEdit } from './edit.ts';

/** What every simple field takes: its label, value, edit callback and tooltip. */
interface FieldProps<T> {
  label: string;
  value: T;
  onEdit: OnEdit<T>;
  title?: string;
}

export function ToggleField({ label, value, onEdit, title }: FieldProps<boolean>) {
  return (
    <label className="kf-field kf-toggle nodrag" title={title}>
      <span className="kf-field__label">{label}</span>
      <input
        type="checkbox"
        aria-label={label}
        checked={value}
        onChange={(e) => onEdit(e.target.checked, true)}
      />
      <span className="kf-toggle__track" aria-hidden="true" />
    </label>
  );
}

export function EnumField({
  label,
  value,
  options,
  onEdit,
  title,
}: FieldProps<string> & { options: readonly string[] }) {
  return (
    <label className="kf-field nodrag" title={title}>
      <span className="kf-field__label">{label}</span>
      <select
        className="kf-input kf-select"
        aria-label={label}
        value={value}
        onChange={(e) => onEdit(e.target.value, true)}
      >
        {options.map((o) => (
          <option key={o} value={o}>
            {o}
          </option>
        ))}
      </select>
    </label>
  );
}

/** Live preview while the picker is open (input events), one commit when it closes (change event). */
export function ColorField({ label, value, onEdit, title }: FieldProps<string>) {
  const ref = useRef<HTMLInputElement>(null);
  const onEditRef = useRef(onEdit);
  onEditRef.current = onEdit;
  useEffect(() => {
    const el = ref.current!;
    const change = () => onEditRef.current(el.value, true);
    el.addEventListener('change', change);
    return () => el.removeEventListener('change', change);
  }, []);
  return (
    <label className="kf-field nodrag" title={title}>
      <span className="kf-field__label">{label}</span>
      <span className="kf-color">
        <input
          ref={ref}
          type="color"
          aria-label={label}
          value={value}
          onChange={(e) => onEdit(e.target.value, false)}
        />
        <code>{value}</code>
      </span>
    </label>
  );
}

/** What is wrong with a text field's saved text, and which characters [start, end) are at fault. */
export interface TextProblem {
  readonly message: string;
  readonly span: readonly [number, number];
}

/**
 * The saved text again, its faulty characters marked (a wavy underline) — an input cannot style
 * part of its text. A span at the end (something missing) marks a space after the last character.
 */
function TextProblemLine({ id, text, problem }: { id: string; text: string; problem: TextProblem }) {
  const start = Math.min(Math.max(problem.span[0], 0), text.length);
  const end = Math.min(Math.max(problem.span[1], start + 1), text.length);
  const bad = text.slice(start, end) || ' ';
  return (
    <span className="kf-field__problem" id={id}>
      <code aria-hidden>
        {text.slice(0, start)}
        <mark>{bad}</mark>
        {text.slice(end)}
      </code>
      <span className="kf-visually-hidden">{problem.message}</span>
    </span>
  );
}

/**
 * A one-line text (a formula, a file name): typed freely, committed as one undo step on Enter or
 * when focus leaves, Esc puts the saved text back; an undo or another tab's edit shows at once.
 * With a `problem`, the field is marked invalid and the characters at fault are underlined under it.
 */
export function TextField({
  label,
  value,
  onEdit,
  title,
  problem,
}: FieldProps<string> & { problem?: TextProblem }) {
  const input = useRef<HTMLInputElement>(null);
  const problemId = useId();
  useEffect(() => {
    if (input.current && document.activeElement !== input.current) input.current.value = value;
  }, [value]);
  const commit = (el: HTMLInputElement) => {
    if (el.value !== value) onEdit(el.value, true);
  };
  return (
    <label className="kf-field kf-field--text nodrag" title={title}>
      <span className="kf-field__label">{label}</span>
      <input
        ref={input}
        className="kf-input"
        aria-label={label}
        aria-invalid={problem ? true : undefined}
        aria-describedby={problem ? problemId : undefined}
        spellCheck={false}
        defaultValue={value}
        onBlur={(e) => commit(e.currentTarget)}
        onKeyDown={(e) => {
          if (e.key === 'Enter') commit(e.currentTarget);
          else if (e.key === 'Escape') e.currentTarget.value = value;
          else return;
          e.stopPropagation();
        }}
      />
      {problem && <TextProblemLine id={problemId} text={value} problem={problem} />}
    </label>
  );
}
