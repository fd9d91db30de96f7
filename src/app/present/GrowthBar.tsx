/**
 * The classroom's growth control, once the picture is shown: draw it with at most 1, 2, 5 or 20
 * inversions, or all of them (paper Figs. 27–28: the tiling after 1, 2, 5, 20 steps), so a class
 * watches the tiling or the quasi-sphere grow. The G key steps to the next depth.
 */
import { GROWTH_DEPTHS } from './construction-steps.ts';

interface Props {
  /** The depth drawn, or null for every inversion (the render's own budget). */
  readonly depth: number | null;
  onDepth(depth: number | null): void;
}

/** The next depth after `depth` in 1, 2, 5, 20, all, and round again. */
export function nextDepth(depth: number | null): number | null {
  if (depth === null) return GROWTH_DEPTHS[0];
  const i = GROWTH_DEPTHS.indexOf(depth as (typeof GROWTH_DEPTHS)[number]);
  return i < 0 || i === GROWTH_DEPTHS.length - 1 ? null : GROWTH_DEPTHS[i + 1]!;
}

export function GrowthBar({ depth, onDepth }: Props) {
  const choices: readonly (number | null)[] = [...GROWTH_DEPTHS, null];
  return (
    <fieldset className="kf-growth" aria-label="Inversions drawn (G)">
      <legend className="kf-growth__label">Inversions</legend>
      {choices.map((d) => (
        <button
          key={d ?? 'all'}
          type="button"
          className={`kf-button${depth === d ? ' kf-button--active' : ''}`}
          aria-pressed={depth === d}
          title={
            d === null ? 'Every inversion (G steps through)' : `At most ${d} inversion${d === 1 ? '' : 's'}`
          }
          onClick={() => onDepth(d)}
        >
          {d ?? 'all'}
        </button>
      ))}
    </fieldset>
  );
}
