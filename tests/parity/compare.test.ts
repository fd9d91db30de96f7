/**
 * The comparison helper itself (no browser): a comparison over too few robust pixels throws instead
 * of reporting a vacuous agreement, and a probe image that disagrees is counted as disagreeing.
 */
import { describe, expect, it } from 'vitest';
import { HAND_MADE_SCENES } from '../shader-gen/support/scenes.ts';
import { assertEnoughCompared, compareColourWithCpu, compareWithCpu } from './compare.ts';
import type { ProbeImage } from './gpu-probe.ts';

const blank = (size: number): ProbeImage =>
  ({ width: size, height: size, data: new Float32Array(size * size * 4), ms: 0 }) as ProbeImage;

describe('compareWithCpu / compareColourWithCpu', () => {
  it('throw when (nearly) every pixel lies near a boundary, instead of agreeing on nothing', () => {
    // Elements thrown together: every path grazes a boundary, so nothing is compared.
    const scene = HAND_MADE_SCENES['every-kind-cosine-edges-clip'];
    expect(() => compareWithCpu(scene, blank(16), { minCompared: 0.5 })).toThrow(/only 0 of 256 pixels/);
    expect(() => compareColourWithCpu(scene, blank(16), { minCompared: 0.5 })).toThrow(/only 0 of 256/);
  });

  it('count a wrong image as wrong over the compared pixels', () => {
    // The empty scene: every point escapes at depth 0 with final = itself; a blank image says
    // depth 0, final (0, 0), not escaped.
    const stats = compareWithCpu(HAND_MADE_SCENES.empty, blank(16), { minCompared: 0.9 });
    expect(stats.compared).toBe(256);
    expect(stats.depthMismatch).toBe(0);
    expect(stats.escapedMismatch).toBe(256);
    expect(stats.agreement).toBe(0);
  });

  it('insist on a share in (0, 1]', () => {
    expect(() => assertEnoughCompared('x', 10, 10, 0)).toThrow(/share/);
    expect(() => assertEnoughCompared('x', 10, 10, 90)).toThrow(/share/);
    expect(() => assertEnoughCompared('x', 9, 10, 0.95)).toThrow(/only 9 of 10/);
    expect(() => assertEnoughCompared('x', 10, 10, 0.95)).not.toThrow();
  });
});
