/**
 * Two panes side by side with a draggable divider (also keyboard: ←/→); the ratio is remembered.
 * On a phone-narrow window (use-narrow.ts) there is room for one pane only: tabs pick the graph,
 * the picture or the inspector (the graph editor again, with its inspector covering it).
 */
import { type ReactNode, useEffect, useRef, useState } from 'react';
import { useNarrow } from './use-narrow.ts';

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

type Tab = 'Graph' | 'Picture' | 'Inspector';
const TABS: readonly Tab[] = ['Graph', 'Picture', 'Inspector'];

interface Props {
  left: ReactNode;
  right: ReactNode;
  /** The left pane as the Inspector tab shows it (narrow windows only). */
  inspector: ReactNode;
  defaultRatio?: number;
}

export function SplitPane(props: Props) {
  return useNarrow() ? <PaneTabs {...props} /> : <Split {...props} />;
}

/** One pane at a time; the picture first, as a phone user comes to look at it. */
function PaneTabs({ left, right, inspector }: Props) {
  const [tab, setTab] = useState<Tab>('Picture');
  // Graph and Inspector are the same editor element in the same slot, so switching keeps its state.
  const pane = tab === 'Picture' ? right : tab === 'Graph' ? left : inspector;
  return (
    <div className="kf-tabs">
      <div className="kf-tabs__list" role="tablist" aria-label="Panes">
        {TABS.map((t) => (
          <button
            key={t}
            type="button"
            role="tab"
            id={`kf-tab-${t}`}
            aria-selected={t === tab}
            aria-controls="kf-tab-panel"
            className={`kf-tabs__tab${t === tab ? ' kf-tabs__tab--on' : ''}`}
            onClick={() => setTab(t)}
          >
            {t}
          </button>
        ))}
      </div>
      <div
        className="kf-split__pane kf-tabs__panel"
        role="tabpanel"
        id="kf-tab-panel"
        aria-labelledby={`kf-tab-${tab}`}
      >
        {pane}
      </div>
    </div>
  );
}

function Split({ left, right, defaultRatio = 0.55 }: Props) {
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
