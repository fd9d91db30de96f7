/**
 * The body of "Explain this pixel" for a volume-rendered 3D graph (inspection-volume.ts): samples
 * taken of those asked for and whether the ray stopped early, the opacity and optical depth, the
 * deepest nesting depth, the pixel's colour, and the depths crossed along the ray as runs, each
 * with the colour its depth emits (none where it is shallower than `from depth`).
 */
import type { InspectionVolume } from './inspection-volume.ts';
import { fmt, GpuLine } from './panel-parts.tsx';

/** Runs listed before the rest is summed up in a note (a ray through many thin shells has many). */
const MAX_RUNS = 40;

export function VolumeFacts({ inspection }: { inspection: InspectionVolume }) {
  const { trace: t, runs } = inspection;
  const shown = runs.slice(0, MAX_RUNS);
  return (
    <>
      <dl className="kf-inspect__facts">
        <dt>Samples</dt>
        <dd>
          <strong data-testid="inspect-samples">{t.samples}</strong> of {t.steps}
          {t.exitedEarly && <span data-testid="inspect-early"> — stopped early (opaque)</span>}
        </dd>
        <dt>Opacity</dt>
        <dd data-testid="inspect-opacity">
          {fmt(100 * t.opacity, 3)} % (optical depth {fmt(t.opticalDepth, 3)})
        </dd>
        <dt>Nesting depth</dt>
        <dd>
          <strong data-testid="inspect-depth">{t.deepest}</strong> at the deepest
        </dd>
        <dt>Colour</dt>
        <dd>
          <span className="kf-inspect__dot" style={{ background: inspection.color }} aria-hidden="true" />
          <span data-testid="inspect-colour">{inspection.color}</span>
        </dd>
        <dt>Ray</dt>
        <dd>
          {t.span
            ? `in the volume from ${fmt(t.span[0], 3)} to ${fmt(t.span[1], 3)}, a sample every ${fmt(t.dt, 3)}`
            : 'misses the volume'}
        </dd>
      </dl>
      <p className="kf-inspect__stop">{inspection.stopText}</p>
      <GpuLine gpu={inspection.gpu} depth={t.deepest} label="GPU samples" />
      {runs.length > 0 && (
        <>
          <h3 className="kf-inspect__word-title">Depth along the ray, front to back</h3>
          <ol className="kf-inspect__word kf-inspect__runs" aria-label="Depth along the ray">
            {shown.map((r, i) => (
              // biome-ignore lint/suspicious/noArrayIndexKey: runs are a fixed sequence, the index is their place on the ray
              <li key={i} data-depth={r.depth}>
                <span className="kf-inspect__name">
                  <span
                    className={`kf-inspect__dot${r.color ? '' : ' kf-inspect__dot--empty'}`}
                    style={r.color ? { background: r.color } : undefined}
                    aria-hidden="true"
                  />
                  depth {r.depth}
                  {r.atLimit && ' (the whole budget: near the limit set)'}
                </span>{' '}
                <span className="kf-inspect__to">
                  × {r.samples} sample{r.samples === 1 ? '' : 's'}
                  {r.color ? '' : ', empty'}
                </span>
              </li>
            ))}
          </ol>
          {runs.length > shown.length && (
            <p className="kf-inspect__note">
              Showing the first {shown.length} of {runs.length} runs of depths.
            </p>
          )}
        </>
      )}
    </>
  );
}
