/**
 * A number: drag the label left/right to scrub (Shift = 10× finer), or type into the field.
 * With both min and max it is a slider. Scrubbing is one gesture (preview, then one commit).
 */
import { useEffect, useRef, useState } from 'react';
import { clamp, formatNumber, type OnEdit, roundToStep } from './edit.ts';

export interface NumberSpec {
  readonly min?: number;
  readonly max?: number;
  readonly step?: number;
  readonly integer?: boolean;
}

interface Props {
  readonly label: string;
  readonly value: number;
  readonly spec: NumberSpec;
  readonly onEdit: OnEdit<number>;
  readonly title?: string;
  /** Hide the label (points show "x"/"y" inside their own row). */
  readonly compact?: boolean;
}

const stepOf = (spec: NumberSpec) => spec.step ?? (spec.integer ? 1 : 0.01);

function normalise(v: number, spec: NumberSpec): number {
  const c = clamp(v, spec.min, spec.max);
  return spec.integer ? Math.round(c) : roundToStep(c, stepOf(spec) / 10);
}

export function NumberField({ label, value, spec, onEdit, title, compact }: Props) {
  const [text, setText] = useState(formatNumber(value));
  const [focused, setFocused] = useState(false);
  const scrub = useRef<{ x: number; start: number; last: number; moved: boolean } | null>(null);
  useEffect(() => {
    if (!focused) setText(formatNumber(value));
  }, [value, focused]);

  const commitText = () => {
    const v = Number(text.trim());
    if (text.trim() !== '' && Number.isFinite(v)) {
      const n = normalise(v, spec);
      if (n !== value) onEdit(n, true);
      setText(formatNumber(n));
    } else setText(formatNumber(value));
  };

  const onPointerDown = (e: React.PointerEvent) => {
    if (e.button !== 0) return;
    e.currentTarget.setPointerCapture(e.pointerId);
    scrub.current = { x: e.clientX, start: value, last: value, moved: false };
  };
  const onPointerMove = (e: React.PointerEvent) => {
    const s = scrub.current;
    if (!s) return;
    const dx = e.clientX - s.x;
    if (!s.moved && Math.abs(dx) < 3) return;
    s.moved = true;
    const perPixel = stepOf(spec) * (e.shiftKey ? 0.1 : 1);
    const v = normalise(spec.integer ? s.start + Math.round(dx / 8) : s.start + dx * perPixel, spec);
    if (v !== s.last) {
      s.last = v;
      onEdit(v, false);
    }
  };
  const onPointerUp = () => {
    const s = scrub.current;
    scrub.current = null;
    if (s?.moved) onEdit(s.last, true);
  };

  const slider = spec.min !== undefined && spec.max !== undefined;
  return (
    <div className={`kf-field kf-number${compact ? ' kf-field--compact' : ''}`} title={title}>
      {!compact && (
        <span
          className="kf-field__label kf-scrub nodrag"
          onPointerDown={onPointerDown}
          onPointerMove={onPointerMove}
          onPointerUp={onPointerUp}
          onPointerCancel={onPointerUp}
          title={`${label}${title ? ` — ${title}` : ''}\nDrag to change (Shift: finer)`}
        >
          {label}
        </span>
      )}
      {slider && (
        <input
          className="kf-slider nodrag"
          type="range"
          aria-label={`${label} slider`}
          min={spec.min}
          max={spec.max}
          step={stepOf(spec)}
          value={value}
          onChange={(e) => onEdit(normalise(Number(e.target.value), spec), false)}
          onPointerUp={(e) => onEdit(normalise(Number(e.currentTarget.value), spec), true)}
          onKeyUp={(e) => onEdit(normalise(Number(e.currentTarget.value), spec), true)}
        />
      )}
      <input
        className="kf-input kf-input--number nodrag"
        aria-label={label}
        inputMode="decimal"
        value={text}
        onFocus={(e) => {
          setFocused(true);
          e.target.select();
        }}
        onBlur={() => {
          setFocused(false);
          commitText();
        }}
        onChange={(e) => setText(e.target.value)}
        onKeyDown={(e) => {
          if (e.key === 'Enter') (e.target as HTMLInputElement).blur();
          if (e.key === 'Escape') {
            setText(formatNumber(value));
            setFocused(false);
            (e.target as HTMLInputElement).blur();
          }
          if (e.key === 'ArrowUp' || e.key === 'ArrowDown') {
            e.preventDefault();
            const n = normalise(value + (e.key === 'ArrowUp' ? 1 : -1) * stepOf(spec), spec);
            onEdit(n, true);
            setText(formatNumber(n));
          }
        }}
      />
    </div>
  );
}
