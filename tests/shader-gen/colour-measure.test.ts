/**
 * Colouring by a measure of the run (docs/math.md "Colouring by a measure"): the measure's value,
 * the palette it goes through, and the orbit trap seeing every point of the path. GPU = CPU for
 * these modes is checked by the parity test's hand-made scenes (schottky-argument, …-orbit-trap).
 */
import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import type { Coloring } from '../../nodes/core/scene.ts';
import { cosinePalette, measureColour, measureValue, orbitTrapDistance } from '../../shader-gen/colour.ts';
import type { IisState } from '../../shader-gen/elements/element-kind.ts';
import { interpret, prepare, runIis } from '../../shader-gen/interpret.ts';
import { sampleColour, sampleContext } from '../../shader-gen/raster.ts';
import { toLinear } from '../../shader-gen/srgb.ts';
import { HAND_MADE_SCENES, measureColoring } from './support/scenes.ts';

type MeasureColoring = Extract<Coloring, { mode: 'measure' }>;
const coloring = (measure: MeasureColoring['measure']) => measureColoring(measure) as MeasureColoring;
const SEED = { seed: 17, numRuns: 200 };
const coord = fc.double({ min: -50, max: 50, noNaN: true });

describe('measureValue', () => {
  it('reads the final point: x, y, |p| and arg p in turns within (−½, ½]', () => {
    fc.assert(
      fc.property(coord, coord, (x, y) => {
        const src = { x, y, s: 1, edge: 0, trap: 0, depth: 0 };
        expect(measureValue(coloring('x'), src)).toBe(x);
        expect(measureValue(coloring('y'), src)).toBe(y);
        expect(measureValue(coloring('radius'), src)).toBeCloseTo(Math.sqrt(x * x + y * y), 9);
        const turns = measureValue(coloring('argument'), src);
        expect(turns).toBeGreaterThanOrEqual(-0.5);
        expect(turns).toBeLessThanOrEqual(0.5);
        // Back to the point's direction: (cos 2πt, sin 2πt)·|p| = p.
        const r = Math.hypot(x, y);
        if (r > 1e-9) {
          expect(r * Math.cos(2 * Math.PI * turns)).toBeCloseTo(x, 6);
          expect(r * Math.sin(2 * Math.PI * turns)).toBeCloseTo(y, 6);
        }
      }),
      SEED,
    );
  });

  it('a colour function reads z = (x, y), the depth n and the scale s; not finite is 0', () => {
    const f = (formula: string) => ({ ...coloring('formula'), formula });
    const src = { x: 3, y: 4, s: 8, edge: 0, trap: 0, depth: 5 };
    expect(measureValue(f('length(z) + n * 10 + log(s) / log(2)'), src)).toBeCloseTo(5 + 50 + 3, 12);
    expect(measureValue(f('x - y'), src)).toBe(-1);
    expect(measureValue(f('1 / (n - 5)'), src)).toBe(0); // ∞ → 0, as the GLSL twin
    expect(measureValue(f('sqrt(-n)'), src)).toBe(0); // NaN → 0
  });

  it('escape speed is ln s: it adds up along a path (ln(s1·s2) = ln s1 + ln s2)', () => {
    fc.assert(
      fc.property(
        fc.double({ min: 1e-3, max: 1e3, noNaN: true }),
        fc.double({ min: 1e-3, max: 1e3, noNaN: true }),
        (s1, s2) => {
          const at = (s: number) =>
            measureValue(coloring('speed'), { x: 0, y: 0, s, edge: 0, trap: 0, depth: 0 });
          expect(at(s1 * s2)).toBeCloseTo(at(s1) + at(s2), 9);
        },
      ),
      SEED,
    );
  });

  it('a point trap measures the distance to it, a circle trap the distance to its rim', () => {
    expect(orbitTrapDistance({ c: [1, 1], r: 0 }, 4, 5)).toBe(5);
    expect(orbitTrapDistance({ c: [0, 0], r: 2 }, 0.5, 0)).toBe(1.5);
    expect(orbitTrapDistance({ c: [0, 0], r: 2 }, 0, -3)).toBe(1);
  });
});

describe('measureColour', () => {
  it('is the cosine palette of offset + scale·m, in linear light', () => {
    const c = { ...coloring('x'), scale: 0.3, offset: 0.2 };
    fc.assert(
      fc.property(coord, (m) => {
        const want = toLinear(cosinePalette(c.a, c.b, c.c, c.d, 0.2 + 0.3 * m));
        expect(measureColour(c, m)).toEqual(want);
      }),
      SEED,
    );
  });
});

describe('the orbit trap sees every point of the path', () => {
  const scene = HAND_MADE_SCENES['triangle-333-orbit-trap'];
  const trap = (scene.tile.coloring as MeasureColoring).trap;
  const pixelWorld = scene.view.scale / 256;

  it('its measure is the least trap distance over the start, every step and the final point', () => {
    const prepared = prepare(scene.elements);
    fc.assert(
      fc.property(
        fc.double({ min: -1.5, max: 1.5, noNaN: true }),
        fc.double({ min: -1.5, max: 1.5, noNaN: true }),
        (x, y) => {
          // Brute force: record every point runIis visits, and take the least distance to the trap.
          const path: [number, number][] = [];
          const st: IisState = { x, y, s: 1, depth: 0 };
          const escaped = runIis(prepared, scene.maxIterations, st, (at) => {
            path.push([at.x, at.y]);
            return false;
          });
          expect(path[0]).toEqual([x, y]);
          expect(path.at(-1)).toEqual([st.x, st.y]);
          const least = Math.min(...path.map(([px, py]) => orbitTrapDistance(trap, px, py)));
          const shaded = { ...scene.tile.coloring, scale: 1, offset: 0 } as MeasureColoring;
          const st2: IisState = { x: 0, y: 0, s: 1, depth: 0 };
          const colour = sampleColour(
            { ...scene, tile: { ...scene.tile, coloring: shaded } },
            sampleContext(scene),
            x,
            y,
            pixelWorld,
            st2,
          );
          if (escaped) expect(colour).toEqual(measureColour(shaded, least));
          // The run itself is the plain IIS: the trap only watches.
          expect(interpret(scene, [x, y]).final).toEqual([st.x, st.y]);
        },
      ),
      { seed: 5, numRuns: 100 },
    );
  });
});
