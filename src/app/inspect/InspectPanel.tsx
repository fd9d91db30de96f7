/**
 * The "Explain this pixel" panel, placed in the render pane away from the clicked point
 * (panel-place.ts): where the point is, why its run stopped and at which depth, the GPU's depth at the same
 * pixel (agreeing, disagreeing with a note, or unavailable and why), the final point and scale, and
 * the word of elements applied — numbered like the markers on the picture. Escape closes it.
 * A 3D graph's explanation (inspection-3d.ts) shows in the same panel: the ray's hit point, the
 * word that maps it onto a seed, and points with three coordinates; a volume-rendered one
 * (inspection-volume.ts) shows what the volume integration did along the ray (VolumeFacts.tsx).
 */
import { type JSX, useCallback } from 'react';
import { MAX_DRAWN_STEPS } from '../../viewport/overlay/orbit-path.ts';
import type { Inspection } from './inspection.ts';
import type { Inspection3d } from './inspection-3d.ts';
import type { InspectionVolume } from './inspection-volume.ts';
import { fmt, GpuLine, point, STOP_TITLE } from './panel-parts.tsx';
import type { PanelPlace } from './panel-place.ts';
import { VolumeFacts } from './VolumeFacts.tsx';

interface Props {
  readonly inspection: Inspection | Inspection3d | InspectionVolume;
  /** Where it goes in the pane (away from the point). */
  readonly place: PanelPlace;
  onClose(): void;
}

export function InspectPanel({ inspection, place, onClose }: Props): JSX.Element {
  // Pan/zoom listens natively on the pane: a press, a drag or a wheel in the panel (Close, selecting
  // text, scrolling the word) must not pan or zoom the picture behind it.
  const keepEvents = useCallback((el: HTMLElement | null) => {
    if (!el) return undefined;
    const stop = (e: Event) => e.stopPropagation();
    el.addEventListener('pointerdown', stop);
    el.addEventListener('wheel', stop);
    return () => {
      el.removeEventListener('pointerdown', stop);
      el.removeEventListener('wheel', stop);
    };
  }, []);
  return (
    <section
      ref={keepEvents}
      className="kf-inspect"
      style={place}
      aria-label="Explain this pixel"
      data-testid="inspect-panel"
    >
      <header className="kf-inspect__head">
        <h2>Explain this pixel</h2>
        <button
          type="button"
          className="kf-inspect__close"
          aria-label="Close"
          title="Close (Esc)"
          onClick={onClose}
        >
          ×
        </button>
      </header>
      {'kind' in inspection && inspection.kind === 'volume' ? (
        <VolumeFacts inspection={inspection} />
      ) : (
        <TraceFacts inspection={inspection} />
      )}
    </section>
  );
}

/** A 2D pixel's or a 3D hit's explanation: the point, the depth, the word. */
function TraceFacts({ inspection }: { inspection: Inspection | Inspection3d }) {
  const { trace: t, word } = inspection;
  const shown = word.slice(0, MAX_DRAWN_STEPS);
  return (
    <>
      <dl className="kf-inspect__facts">
        <dt>{'kind' in inspection ? 'Hit point' : 'Point'}</dt>
        <dd data-testid="inspect-point">{t.stop === 'missed' ? '—' : point(t.start)}</dd>
        <dt>Depth</dt>
        <dd>
          <strong data-testid="inspect-depth">{t.depth}</strong> — {STOP_TITLE[t.stop]}
        </dd>
        <dt>Final</dt>
        <dd>
          {point(t.final)}, scale ×{fmt(t.scale)}
        </dd>
      </dl>
      <p className="kf-inspect__stop">{inspection.stopText}</p>
      <GpuLine gpu={inspection.gpu} depth={t.depth} />
      {word.length > 0 && (
        <>
          <h3 className="kf-inspect__word-title">Word: the elements applied, in order</h3>
          <ol className="kf-inspect__word" aria-label="Word">
            {shown.map((l) => (
              <li key={l.step} data-power={l.power}>
                <span className="kf-inspect__name">
                  <span className="kf-inspect__dot" style={{ background: l.color }} aria-hidden="true" />
                  {l.name}
                  {l.power > 1 && <sup title={`a fold by ${l.power} steps`}>{l.power}</sup>}
                </span>
                <span className="kf-inspect__to">
                  → {point(l.at, 3)} ×{fmt(l.factor, 3)}
                </span>
              </li>
            ))}
          </ol>
          {word.length > shown.length && (
            <p className="kf-inspect__note">
              Showing the first {shown.length} of {word.length} steps (here and on the picture).
            </p>
          )}
        </>
      )}
    </>
  );
}
