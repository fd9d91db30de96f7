/**
 * The model behind "Explain this pixel" in volume mode (src/app/inspect/inspection-volume.ts), on the
 * Fig. 10 example: its runs are the CPU volume renderer's, coloured by the palette of their depth
 * (none for depths shallower than `from depth`), the pixel's colour is the ray's, and the sentence
 * says whether the ray missed the mirrors, stopped early (opaque) or let the background through.
 */
import { describe, expect, it } from 'vitest';
import { toHex } from '../../../../nodes/core/port-values.ts';
import type { Scene3d } from '../../../../nodes/core/scene-3d.ts';
import { explainVolumePixel3d } from '../../../../shader-gen/space/explain-volume-3d.ts';
import { inspectVolume } from '../../../../src/app/inspect/inspection-volume.ts';
import { exampleScenes3d } from '../../../shader-gen/space/scenes-3d.ts';

const W = 64;
const H = 48;
const FIG10 = exampleScenes3d()['fig10-volume-nesting-spheres']!;
const explain = (scene: Scene3d, x: number, y: number) => inspectVolume(scene, scene.camera, [x, y], W, H);
/** A pixel on the middle row whose ray crosses a mirror (some sample of depth ≥ 1). */
const inMirror = (): [number, number] => {
  for (let x = W / 2; x < W; x++) if (explain(FIG10, x, H / 2).trace.deepest >= 1) return [x, H / 2];
  throw new Error('no ray through a mirror on the middle row');
};

describe('inspectVolume', () => {
  it('is the volume renderer’s ray at the pixel (y down in CSS), its runs coloured by depth', () => {
    const r = explain(FIG10, W / 2, H / 2 - 3);
    expect(r.kind).toBe('volume');
    expect(r.trace).toEqual(explainVolumePixel3d(FIG10, W, H, W / 2, H / 2 + 3));
    expect(r.color).toBe(toHex(r.trace.colour));
    expect(r.runs.map((x) => [x.depth, x.samples])).toEqual(r.trace.runs.map((x) => [x.depth, x.samples]));
    const v = FIG10.volume!;
    for (const run of r.runs) expect(run.color === null).toBe(run.depth < v.depthFrom);
    expect(r.runs.some((x) => x.depth >= 2)).toBe(true); // through the centre: nested images
    // Depths from `to depth` on share the palette's end.
    const deep = r.runs.filter((x) => x.depth >= v.depthTo).map((x) => x.color);
    expect(new Set(deep).size).toBeLessThanOrEqual(1);
    expect(r.gpu.kind).toBe('unavailable');
  });

  it('says when the ray passes outside every mirror', () => {
    const r = explain(FIG10, 0.5, 0.5);
    expect(r.trace.span).toBeNull();
    expect(r.runs).toEqual([]);
    expect(r.stopText).toMatch(/outside the ball holding every mirror/);
    expect(r.color).toBe(toHex(FIG10.background));
  });

  it('says when the ray turned opaque and stopped early, and when the background shows through', () => {
    const dense = { ...FIG10, volume: { ...FIG10.volume!, density: 60 } };
    const [x, y] = inMirror();
    const early = explain(dense, x, y);
    expect(early.trace.exitedEarly).toBe(true);
    expect(early.stopText).toMatch(
      new RegExp(
        `99 % opaque after sample ${early.trace.samples} of ${FIG10.volume!.steps} and stopped early`,
      ),
    );
    const thin = { ...FIG10, volume: { ...FIG10.volume!, density: 0.05, growth: 1 } };
    const through = explain(thin, x, y);
    expect(through.trace.exitedEarly).toBe(false);
    expect(through.stopText).toMatch(/opaque at the end: the rest of the pixel is the background/);
  });
});
