/**
 * One polite live region for the whole app, so a screen reader hears what changed without the
 * focus moving: a wire made, a handle moved, a new warning. Made on first use (outside React, so
 * any module can announce without threading a callback through props).
 */

let region: HTMLElement | null = null;
let pending: ReturnType<typeof setTimeout> | undefined;

/** The live region (made once; kept in the page for the app's life). */
export function liveRegion(): HTMLElement | null {
  if (typeof document === 'undefined') return null;
  if (region?.isConnected) return region;
  region = document.createElement('div');
  region.className = 'kf-visually-hidden';
  region.setAttribute('role', 'status');
  region.setAttribute('aria-live', 'polite');
  region.dataset.testid = 'announcer';
  document.body.append(region);
  return region;
}

let queued: string[] = [];

/**
 * Says `text` politely. The text is set a moment after the region exists and after clearing it, so
 * screen readers announce a region that was just created and the same sentence said twice; what is
 * said in that moment (a wire, then the warning it caused) is said together, not overwritten.
 */
export function announce(text: string): void {
  const el = liveRegion();
  if (!el) return;
  clearTimeout(pending);
  queued.push(text);
  el.textContent = '';
  pending = setTimeout(() => {
    el.textContent = queued.join('. ');
    queued = [];
  }, 60);
}
