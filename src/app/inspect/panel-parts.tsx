/**
 * Parts of the "Explain this pixel" panel shared by its 2D, 3D and volume bodies: numbers for
 * people, points, the stop titles and the line on the GPU's depth.
 */
import type { GpuCheck } from './inspection.ts';

/** A number for people: `digits` significant digits, no exponent for ordinary sizes, a true minus sign. */
export const fmt = (v: number, digits = 4): string => {
  if (!Number.isFinite(v)) return String(v);
  const a = Math.abs(v);
  const text =
    a !== 0 && (a >= 1e6 || a < 1e-4) ? v.toExponential(digits - 1) : String(+v.toPrecision(digits));
  return text.replace(/-/g, '−');
};
export const point = (p: readonly number[], digits = 4) => `(${p.map((v) => fmt(v, digits)).join(', ')})`;

export const STOP_TITLE = {
  'fundamental-domain': 'reached the tile',
  limit: 'hit the limit',
  seed: 'in an orbit seed',
  clipped: 'outside the clip disk',
  missed: 'the ray misses the orbit',
} as const;

/** What the GPU's answer is compared with: `label` names it ("GPU depth", "GPU samples"). */
export function GpuLine({
  gpu,
  depth,
  label = 'GPU depth',
}: {
  gpu: GpuCheck;
  depth: number;
  label?: string;
}) {
  if (gpu.kind === 'agrees')
    return (
      <p className="kf-inspect__gpu kf-inspect__gpu--agrees" data-testid="inspect-gpu">
        GPU depth: {gpu.depth} (agrees)
      </p>
    );
  if (gpu.kind === 'unavailable')
    return (
      <p className="kf-inspect__gpu kf-inspect__gpu--unavailable" data-testid="inspect-gpu">
        {label}: not available — {gpu.reason}.
      </p>
    );
  return (
    <div className="kf-inspect__gpu kf-inspect__gpu--disagrees" role="alert" data-testid="inspect-gpu">
      <p>
        GPU depth: {gpu.depth} ({STOP_TITLE[gpu.stop]}) — disagrees with the CPU's {depth}.
      </p>
      <p className="kf-inspect__note">{gpu.note}</p>
    </div>
  );
}
