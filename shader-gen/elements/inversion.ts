/** Circle inversion (c, r): inside |p−c| < r; σ(p) = c + r²(p−c)/|p−c|²; scale r²/|p−c|². */
import type { InversionElement } from '../../nodes/core/scene.ts';
import type { ElementKind, IisState } from './element-kind.ts';

/**
 * The point exactly at an inversion centre maps to ∞ (r²/0): it goes instead to the far point
 * c + (r·G, 0) with scale G², as if it lay r/G to the right of c (G = CENTRE_GUARD), so the run
 * stays finite and the GPU twin does the same. Written without a branch or a choice, so that the
 * GPU twin is pure arithmetic (SwiftShader pays for an `if` or a `?:` here with about a third of
 * an inversion-heavy frame, tests/bench/shader-ratio.ts): k = min(r²/|p−c|², G²) — r²/0 = ∞
 * becomes G², which also caps k within r/G of the centre — and x gains r·G only at the centre.
 */
export const CENTRE_GUARD = 1e9;

/** Inverts the state's point in (cx, cy, r) unconditionally; shared by the generator kinds. */
export function invertState(st: IisState, cx: number, cy: number, r: number): void {
  const dx = st.x - cx;
  const dy = st.y - cy;
  const d2 = dx * dx + dy * dy;
  const k = Math.min((r * r) / d2, CENTRE_GUARD * CENTRE_GUARD);
  // At the centre dx·k = dy·k = 0: x = cx + r·G, y = cy, scale G².
  st.x = cx + dx * k + (d2 === 0 ? 1 : 0) * (r * CENTRE_GUARD);
  st.y = cy + dy * k;
  st.s *= k;
}

export const inversion: ElementKind<InversionElement> = {
  kind: 'inversion',
  step(e, st) {
    const dx = st.x - e.c[0];
    const dy = st.y - e.c[1];
    if (dx * dx + dy * dy >= e.r * e.r) return false;
    invertState(st, e.c[0], e.c[1], e.r);
    st.depth += 1;
    return true;
  },
  inside: (e, x, y) => (x - e.c[0]) ** 2 + (y - e.c[1]) ** 2 < e.r * e.r,
  boundaryDistance: (e, x, y) => Math.abs(Math.hypot(x - e.c[0], y - e.c[1]) - e.r),
};
