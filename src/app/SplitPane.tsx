/** Two panes side by side with a draggable divider (also keyboard: ←/→); the ratio is remembered. */
import { type ReactNode, useEffect, useRef, useState } from 'react';

const KEY = 'kleinflow.split';
const MIN_PX = 280;

function initialRatio(fallback: number): number {
  try {
    const v = Number(localStorage.getItem(KEY));
    return v > 0.1 && v < 0.9 ? v : fallback;
  } catch {
    return fallback;
  }
}

export function SplitPane({
  left,
  right,
  defaultRatio = 0.55,
}: {
  left: ReactNode;
  right: ReactNode;
  defaultRatio?: number;
}) {
  const [ratio, setRatio] = useState(() => initialRatio(defaultRatio));
  const root = useRef<HTMLDivElement>(null);
  const dragging = useRef(false);
  useEffect(() => {
    try {
      localStorage.setItem(KEY, String(ratio));
    } catch {
      // not critical: the split falls back to the default next time
    }
  }, [ratio]);

  const clampRatio = (r: number) => {
    const width = root.current?.clientWidth ?? 1000;
    return Math.min(1 - MIN_PX / width, Math.max(MIN_PX / width, r));
  };
  return (
    <div className="kf-split" ref={root} style={{ gridTemplateColumns: `${ratio}fr 6px ${1 - ratio}fr` }}>
      <div className="kf-split__pane">{left}</div>
      {/* biome-ignore lint/a11y/useSemanticElements: a draggable splitter, not a rule */}
      <div
        className="kf-split__divider"
        role="separator"
        aria-orientation="vertical"
        aria-label="Resize panes"
        aria-valuenow={Math.round(ratio * 100)}
        tabIndex={0}
        onPointerDown={(e) => {
          e.currentTarget.setPointerCapture(e.pointerId);
          dragging.current = true;
        }}
        onPointerMove={(e) => {
          if (!dragging.current) return;
          const rect = root.current!.getBoundingClientRect();
          setRatio(clampRatio((e.clientX - rect.left) / rect.width));
        }}
        onPointerUp={() => {
          dragging.current = false;
        }}
        onKeyDown={(e) => {
          if (e.key === 'ArrowLeft') setRatio((r) => clampRatio(r - 0.02));
          if (e.key === 'ArrowRight') setRatio((r) => clampRatio(r + 0.02));
        }}
      />
      <div className="kf-split__pane">{right}</div>
    </div>
  );
}
