/**
 * The docked inspector's width: clamped so the graph canvas always keeps room, remembered in
 * localStorage (a UI preference, never part of the document).
 */
import { useCallback, useState } from 'react';

export const PANEL_WIDTH = {
  /** The width a first visit gets. */
  initial: 300,
  min: 220,
  max: 640,
  /** The canvas beside the panel never gets narrower than this. */
  canvasMin: 240,
  /** One arrow key press (Shift: four). */
  step: 16,
} as const;

/** `width` kept within [min, max] and leaving `canvasMin` of an `areaWidth` wide area (0 = unknown). */
export function clampPanelWidth(width: number, areaWidth: number): number {
  const roomy = areaWidth > 0 ? areaWidth - PANEL_WIDTH.canvasMin : PANEL_WIDTH.max;
  const max = Math.max(PANEL_WIDTH.min, Math.min(PANEL_WIDTH.max, roomy));
  const w = Number.isFinite(width) ? width : PANEL_WIDTH.initial;
  return Math.round(Math.min(max, Math.max(PANEL_WIDTH.min, w)));
}

export function usePanelWidth(key: string): [number, (w: number) => void] {
  const [width, setWidth] = useState(() => {
    try {
      const v = Number(localStorage.getItem(key));
      return v > 0 ? clampPanelWidth(v, 0) : PANEL_WIDTH.initial;
    } catch {
      return PANEL_WIDTH.initial;
    }
  });
  const set = useCallback(
    (w: number) => {
      setWidth(w);
      try {
        localStorage.setItem(key, String(w));
      } catch {
        // a width that is not remembered is not worth an error
      }
    },
    [key],
  );
  return [width, set];
}
