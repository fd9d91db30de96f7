/**
 * The element registry (shader-gen/elements/index.ts): every element kind of the Scene union has
 * ONE record holding both halves — a CPU half that keeps the step/inside/boundaryDistance contract,
 * and a GLSL half whose packing fills its vec4s and whose code compiles (glslangValidator), alone
 * and uniform or baked. The type-level checks at the end make a record without its GLSL half, or a
 * registry without a kind, a `tsc` error.
 */
import { describe, expect, it } from 'vitest';
import type { InversionElement, SceneElement } from '../../../nodes/core/scene.ts';
import { compile } from '../../../shader-gen/compile.ts';
import type { ElementRecord, IisState } from '../../../shader-gen/elements/element-kind.ts';
import { ELEMENTS, type ElementRegistry, elementRecord } from '../../../shader-gen/elements/index.ts';
import { inversion } from '../../../shader-gen/elements/inversion.ts';
import { validateShaders } from '../support/glslang.ts';
import { EVERY_KIND, makeScene } from '../support/scenes.ts';

const KINDS = Object.keys(ELEMENTS).sort();

/** One sample element of each kind (the first of it in EVERY_KIND). */
const SAMPLES: readonly SceneElement[] = KINDS.map((kind) => EVERY_KIND.find((e) => e.kind === kind)!);

/** A 21 × 21 grid over [−3, 3]², off the axes by a hair so no point sits on a symmetry line. */
const GRID: readonly [number, number][] = Array.from({ length: 21 * 21 }, (_, i) => [
  -3 + 0.3 * (i % 21) + 1e-3,
  -3 + 0.3 * Math.floor(i / 21) + 2e-3,
]);

describe('every element kind has one record with a CPU and a GLSL half', () => {
  it('the registry is keyed by kind, and the hand-made scenes use every kind', () => {
    for (const [kind, record] of Object.entries(ELEMENTS)) expect(record.kind).toBe(kind);
    expect([...new Set(EVERY_KIND.map((e) => e.kind))].sort()).toEqual(KINDS);
    for (const e of SAMPLES) expect(elementRecord(e)).toBe(ELEMENTS[e.kind]);
  });

  for (const e of SAMPLES) {
    it(`${e.kind}: CPU step applies exactly where inside holds; boundaryDistance ≥ 0`, () => {
      const { cpu } = elementRecord(e);
      let applied = 0;
      for (const [x, y] of GRID) {
        const st: IisState = { x, y, s: 1, depth: 0 };
        const inside = cpu.inside(e, x, y);
        expect(cpu.step(e, st)).toBe(inside);
        if (inside) {
          applied++;
          expect(st.depth).toBeGreaterThanOrEqual(1);
        } else expect(st).toEqual({ x, y, s: 1, depth: 0 });
        const d = cpu.boundaryDistance(e, x, y);
        expect(d).toBeGreaterThanOrEqual(0);
        expect(Number.isFinite(d)).toBe(true);
      }
      expect(applied).toBeGreaterThan(0);
    });

    it(`${e.kind}: GLSL packing fills its ${elementRecord(e).glsl.vec4s} vec4(s) with finite numbers`, () => {
      const { glsl } = elementRecord(e);
      const data = glsl.pack(e);
      expect(data).toHaveLength(4 * glsl.vec4s);
      expect(data.every(Number.isFinite)).toBe(true);
    });
  }

  it('each GLSL half compiles alone (uniform and baked, with its inside and boundary distance)', () => {
    const shaders = SAMPLES.flatMap((e) =>
      [false, true].map((baked) => {
        const program = compile(makeScene([e], { edgeWidth: 1 }), { baked });
        const { glsl } = elementRecord(e);
        // The step block, the inside and the boundary distance are all in the program.
        expect(program.source).toContain(glsl.step.code.split('\n')[0]);
        expect(program.source).toContain(`${glsl.inside.name}(vec2 p`);
        expect(program.source).toContain(`${glsl.boundaryDistance.name}(vec2 p`);
        return {
          name: `${e.kind}-${baked ? 'baked' : 'uniform'}`,
          source: program.source,
          stage: 'frag' as const,
        };
      }),
    );
    const results = validateShaders(shaders);
    for (const s of shaders)
      expect({ name: s.name, errors: results.get(s.name) }).toEqual({ name: s.name, errors: [] });
  });
});

/**
 * Type-level: each line under a @ts-expect-error must NOT type-check, and `tsc` (npm test) fails on
 * an expect-error that has no error to expect. Never called: the checks happen at compile time.
 */
function typeChecks(): unknown[] {
  // @ts-expect-error a record without its GLSL half is not an ElementRecord
  const cpuOnly: ElementRecord<InversionElement> = { kind: 'inversion', cpu: inversion.cpu };
  // @ts-expect-error nor is one without its CPU half
  const glslOnly: ElementRecord<InversionElement> = { kind: 'inversion', glsl: inversion.glsl };
  const { inversion: _, ...withoutInversion } = ELEMENTS;
  // @ts-expect-error a registry that lacks a kind of the Scene union
  const partial: ElementRegistry = withoutInversion;
  // @ts-expect-error a record filed under another kind
  const misfiled: ElementRegistry = { ...ELEMENTS, reflection: inversion };
  return [cpuOnly, glslOnly, partial, misfiled];
}
void typeChecks;
