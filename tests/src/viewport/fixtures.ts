/**
 * Scenes for the viewport tests: the shipped hyperbolic example (through the real loader and
 * evaluator) and a small Apollonian-like set of three inversion circles whose first circle can
 * be moved (same structure, new values: what a drag does).
 */
import { readFileSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import { DEFAULT_TILE, type Scene, type View } from '../../../nodes/core/scene.ts';
import type { Vec2 } from '../../../nodes/core/values.ts';
import { evaluateGraph } from '../../../nodes/graph/evaluate.ts';
import { parseDocumentText } from '../../../nodes/graph/load.ts';
import { registry } from '../../../nodes/types/index.ts';

export function exampleScene(name: string): Scene {
  const path = fileURLToPath(new URL(`../../../examples/${name}.kleinflow.json`, import.meta.url));
  const loaded = parseDocumentText(readFileSync(path, 'utf8'), registry);
  if (!loaded.ok) throw new Error(`example ${name}: ${loaded.diagnostics.map((d) => d.message).join('; ')}`);
  return evaluateGraph(loaded.doc, registry).scene;
}

export const CIRCLES_VIEW: View = { center: [0, 0], scale: 3 };

/** Three mutually tangent-ish circles (node ids c1, c2, c3); `first` moves the first one. */
export function circlesScene(first: Vec2 = [-0.55, -0.3], samples = 8, extra = false): Scene {
  const circle = (nodeId: string, c: Vec2, r: number) => ({ kind: 'inversion' as const, nodeId, c, r });
  return {
    elements: [
      circle('c1', first, 0.6),
      circle('c2', [0.55, -0.3], 0.6),
      circle('c3', [0, 0.65], 0.6),
      ...(extra ? [circle('c4', [0, -0.05], 0.12)] : []),
    ],
    tile: DEFAULT_TILE,
    maxIterations: 40,
    samples,
    clip: null,
    view: CIRCLES_VIEW,
    overlays: [],
    handles: [],
    renderNodeId: 'out',
  };
}

/** Per-channel absolute differences of two RGBA images: mean (in 1/255 units) and the share of pixels off by more than `tol`. */
export function compareImages(a: Uint8Array, b: Uint8Array, tol = 0): { mean: number; offShare: number } {
  if (a.length !== b.length) throw new Error(`image sizes differ: ${a.length} vs ${b.length}`);
  let sum = 0;
  let off = 0;
  for (let i = 0; i < a.length; i += 4) {
    let worst = 0;
    for (let c = 0; c < 4; c++) {
      const d = Math.abs(a[i + c] - b[i + c]);
      sum += d;
      worst = Math.max(worst, d);
    }
    if (worst > tol) off++;
  }
  return { mean: sum / a.length, offShare: off / (a.length / 4) };
}

/** How many different RGB colours an image has (a blank one has 1). */
export function colourCount(a: Uint8Array): number {
  const seen = new Set<number>();
  for (let i = 0; i < a.length; i += 4) seen.add((a[i] << 16) | (a[i + 1] << 8) | a[i + 2]);
  return seen.size;
}
