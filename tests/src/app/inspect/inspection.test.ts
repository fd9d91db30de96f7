/**
 * The model behind the "Explain this pixel" panel: the word and its colours, the stop sentence, and
 * the GPU check — agreeing, disagreeing (shown with a note, never hidden) or unavailable.
 */
import { describe, expect, it } from 'vitest';
import { evaluateGraph } from '../../../../nodes/graph/evaluate.ts';
import { registry } from '../../../../nodes/types/index.ts';
import { tracePicture } from '../../../../shader-gen/trace.ts';
import { inspect } from '../../../../src/app/inspect/inspection.ts';
import type { GpuPixelResult } from '../../../../src/viewport/pixel-probe.ts';
import { loadExample } from '../../../support/examples.ts';

const evaluation = (name: string) => evaluateGraph(loadExample(name).doc, registry);
const probe = (world: [number, number], gpu: GpuPixelResult) => ({
  pixel: { px: 0, py: 0, width: 1, height: 1 },
  world,
  gpu,
});

describe('inspect', () => {
  const ev = evaluation('hyperbolic-237');
  const p: [number, number] = [0.9, -0.1];
  const t = tracePicture(ev.scene, p);

  it('names every step, numbers it, and tells the three mirrors apart by colour', () => {
    const gpu = { ok: true, pixel: { depth: t.depth, final: t.final, stop: t.stop, seed: -1 } } as const;
    const r = inspect(ev, probe(p, gpu));
    expect(r.gpu).toEqual({ kind: 'agrees', depth: t.depth });
    expect(r.word.map((l) => l.step)).toEqual(t.steps.map((_, i) => i + 1));
    expect(r.word.reduce((n, l) => n + l.power, 0)).toBe(t.depth);
    for (const l of r.word) expect(l.name).toMatch(/^Triangle kaleidoscope [123]$/);
    const colours = new Map(r.word.map((l) => [l.name, l.color]));
    expect(new Set(colours.values()).size).toBe(colours.size);
    expect(r.stopText).toBe(`Reached the tile (the fundamental domain) after ${t.depth} steps.`);
  });

  it('shows a disagreement with the GPU, and says why it may happen', () => {
    const gpu = { ok: true, pixel: { depth: t.depth + 1, final: t.final, stop: 'limit', seed: -1 } } as const;
    const r = inspect(ev, probe(p, gpu));
    expect(r.gpu).toMatchObject({ kind: 'disagrees', depth: t.depth + 1, stop: 'limit' });
    // This point is far from every mirror: not a rounding difference.
    expect(r.gpu.kind === 'disagrees' && r.gpu.note).toMatch(/not rounding/);
    // On a mirror (the real axis, y = 0) float32 and float64 may branch differently.
    const onMirror: [number, number] = [0.5, 1e-12];
    const near = tracePicture(ev.scene, onMirror);
    const off = {
      ok: true,
      pixel: { depth: near.depth + 1, final: near.final, stop: near.stop, seed: -1 },
    } as const;
    const r2 = inspect(ev, probe(onMirror, off));
    expect(r2.gpu.kind === 'disagrees' && r2.gpu.note).toMatch(/float32 rounding of a mirror/);
  });

  it('says honestly when there is no GPU answer', () => {
    const r = inspect(ev, probe(p, { ok: false, reason: 'the WebGL context is lost' }));
    expect(r.gpu).toEqual({ kind: 'unavailable', reason: 'the WebGL context is lost' });
  });

  it('explains a point outside the clip disk and a point that lands in an orbit seed', () => {
    const none = { ok: false, reason: 'test' } as const;
    const outside = inspect(ev, probe([5, 5], none));
    expect(outside.trace.stop).toBe('clipped');
    expect(outside.stopText).toMatch(/Outside the clip disk/);
    const frieze = evaluation('glide-reflection-frieze');
    const seed = frieze.scene.tile.seeds![0];
    if (seed.kind !== 'disk') throw new Error('expected a disk seed');
    const r = inspect(frieze, probe([seed.c[0], seed.c[1]], none));
    expect(r.trace.stop).toBe('seed');
    expect(r.stopText).toMatch(/^Landed in the orbit seed “.+” after 0 steps/);
  });
});
