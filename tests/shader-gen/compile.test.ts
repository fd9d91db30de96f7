/**
 * compile(): the contract the WebGL runtime relies on — the shape of the program, where values
 * go (uniforms sorted by name, or literals), the source as the program's identity (values never
 * change it, code always does), `#line` mapping, the limits reported as diagnostics, determinism.
 */
import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import { type Coloring, LIMITS, type Scene, type SceneElement } from '../../nodes/core/scene.ts';
import { compile, FRAME_UNIFORMS, shadertoySource } from '../../shader-gen/compile.ts';
import { elementRecord } from '../../shader-gen/elements/index.ts';
import { FLOAT32_MAX, floatLiteral } from '../../shader-gen/glsl/literal.ts';
import { uniformRows } from '../../shader-gen/glsl/values.ts';
import {
  COLORINGS,
  EVERY_KIND,
  HAND_MADE_SCENES,
  makeScene,
  measureColoring,
  reflection,
  TRIANGLE_333,
} from './support/scenes.ts';

const scenes = Object.entries(HAND_MADE_SCENES);
const withElements = (s: Scene, elements: readonly SceneElement[]): Scene => ({ ...s, elements });

/** Every number inside the scene's elements, tile and clip moved a little (booleans kept). */
function nudged(scene: Scene, amount: number): Scene {
  const nudge = <T>(v: T): T => {
    if (typeof v === 'number') return (v * (1 + amount) + amount) as T;
    if (Array.isArray(v)) return v.map(nudge) as T;
    if (v && typeof v === 'object') {
      return Object.fromEntries(
        Object.entries(v).map(([k, x]) => [k, k === 'nodeId' || k === 'mode' ? x : nudge(x)]),
      ) as T;
    }
    return v;
  };
  const order = (e: SceneElement): SceneElement => (e.kind === 'rotation' ? { ...e, order: 7 } : e);
  return {
    ...scene,
    elements: nudge(scene.elements).map(order),
    // Edges on/off is structure: keep a zero width zero.
    tile: {
      ...nudge(scene.tile),
      edgeWidth: scene.tile.edgeWidth === 0 ? 0 : scene.tile.edgeWidth + 0.5,
      // …and so is the limit-set glow on/off.
      coloring:
        scene.tile.coloring.mode === 'limit-set'
          ? { mode: 'limit-set', glow: scene.tile.coloring.glow === 0 ? 0 : scene.tile.coloring.glow + 1 }
          : nudge(scene.tile.coloring),
    },
    clip: nudge(scene.clip),
    maxIterations: scene.maxIterations + 17,
  };
}

describe('program shape', () => {
  for (const [name, scene] of scenes) {
    it(`${name}: every variant starts with #version, declares the frame uniforms, and has an entry point`, () => {
      for (const options of [{}, { baked: true }, { variant: 'probe' as const }]) {
        const p = compile(scene, options);
        expect(p.source.startsWith('#version 300 es\n')).toBe(true);
        expect(p.vertexSource.startsWith('#version 300 es\n')).toBe(true);
        for (const u of FRAME_UNIFORMS) expect(p.source).toContain(`uniform ${u.type} ${u.name};`);
        expect(p.source).toMatch(/\nvoid main\(\) \{/);
        expect(p.source).not.toMatch(/\bswitch\b/);
      }
    });
  }

  it('the colour variant writes outColor, the probe variant outProbe (depth, final, escaped)', () => {
    const scene = HAND_MADE_SCENES['schottky-cosine-edges'];
    expect(compile(scene).source).toMatch(
      /outColor = shadeSample\(w, u_view\.z \/ u_resolution\.y, u_bgAlpha\);/,
    );
    expect(compile(scene, { variant: 'probe' }).source).toContain(
      'outProbe = vec4(float(depth), p, escaped ? 1.0 : 0.0);',
    );
  });

  it('the probe variant reads only the element data and the iteration bound', () => {
    const p = compile(HAND_MADE_SCENES['every-kind-cosine-edges-clip'], { variant: 'probe' });
    expect(p.uniforms.map((u) => u.name)).toEqual(['u_el', 'u_maxIterations']);
  });
});

describe('uniforms', () => {
  for (const [name, scene] of scenes) {
    it(`${name}: sorted by name, finite, sized by type; u_el holds each element's packed vec4s`, () => {
      const p = compile(scene);
      const names = p.uniforms.map((u) => u.name);
      expect(names).toEqual([...names].sort());
      for (const u of p.uniforms) {
        expect(u.value.every(Number.isFinite)).toBe(true);
        const size = { float: 1, int: 1, vec2: 2, vec3: 3, vec4: 4 }[u.type as 'float'];
        if (size) expect(u.value.length).toBe(size);
        expect(p.source).toMatch(new RegExp(`uniform \\w+ ${u.name}(\\[\\d+\\])?;`));
      }
      const el = p.uniforms.find((u) => u.name === 'u_el');
      const packed = scene.elements.flatMap((e) => elementRecord(e).glsl.pack(e));
      expect(el?.value ?? []).toEqual(packed);
      expect(p.uniforms.find((u) => u.name === 'u_maxIterations')?.value).toEqual([scene.maxIterations]);
    });

    it(`${name}: baked has no scene uniforms and carries the values as literals`, () => {
      const p = compile(scene, { baked: true });
      expect(p.uniforms).toEqual([]);
      const declared = [...p.source.matchAll(/^uniform (?!sampler2D)\w+ (\w+)/gm)].map((m) => m[1]);
      expect(declared).toEqual(FRAME_UNIFORMS.map((u) => u.name));
      // Pictures stay samplers (a texture cannot be a literal): u_image0, u_image1, …
      const samplers = [...p.source.matchAll(/^uniform sampler2D (\w+)/gm)].map((m) => m[1]);
      expect(samplers).toEqual(p.pictures.map((_, i) => `u_image${i}`));
      expect(p.source).toContain(`for (; depth < ${scene.maxIterations}; ++depth)`);
    });
  }
});

/**
 * The source text is the program's identity (src/viewport/program-cache.ts keys on it): a value edit
 * must give the same text byte for byte (no recompile while dragging), and every change of the code
 * a different text (or the new code would never be compiled).
 */
describe('program identity: the source changes with the code, never with values', () => {
  it('a uniform program: any change of values gives the same source and new uniforms', () => {
    fc.assert(
      fc.property(
        fc.constantFrom(...scenes),
        fc.double({ min: -0.2, max: 0.2, noNaN: true }),
        ([, scene], d) => {
          const a = compile(scene);
          const b = compile(nudged(scene, d));
          expect(b.source).toBe(a.source);
          if (Math.abs(d) > 1e-6 && scene.elements.length > 0) expect(b.uniforms).not.toEqual(a.uniforms);
        },
      ),
      { seed: 42, numRuns: 60 },
    );
  });

  it('changes with the element kinds, their order or number, colouring, edges, clip, variant, baking', () => {
    const base = HAND_MADE_SCENES['triangle-333-parity-clip'];
    const source = (s: Scene, o = {}) => compile(s, o).source;
    const variants: Scene[] = [
      withElements(base, [...TRIANGLE_333, reflection('m4', [0, 0], [1, 0])]),
      withElements(base, [TRIANGLE_333[0], TRIANGLE_333[1]]),
      withElements(base, [...TRIANGLE_333.slice(0, 2), EVERY_KIND[3]]),
      withElements(base, [EVERY_KIND[3], ...TRIANGLE_333.slice(0, 2)]),
      { ...base, tile: { ...base.tile, coloring: COLORINGS.cosine } },
      { ...base, tile: { ...base.tile, coloring: COLORINGS['depth-hsv'] } },
      { ...base, tile: { ...base.tile, edgeWidth: 1 } },
      { ...base, clip: null },
    ];
    const sources = [
      source(base),
      ...variants.map((s) => source(s)),
      source(base, { variant: 'probe' }),
      source(base, { baked: true }),
    ];
    expect(new Set(sources).size).toBe(sources.length);
  });

  it('baked: values are code, so maxIterations and any value change the source', () => {
    const base = HAND_MADE_SCENES['strips-hsv-edges'];
    const a = compile(base, { baked: true }).source;
    expect(a).toContain(`depth < ${base.maxIterations};`);
    expect(compile({ ...base, maxIterations: 101 }, { baked: true }).source).not.toBe(a);
    expect(compile(nudged(base, 0.01), { baked: true }).source).not.toBe(a);
    expect(compile({ ...base, maxIterations: 101 }).source).toBe(compile(base).source);
  });
});

describe('determinism and #line markers', () => {
  it('the same scene gives the same source byte for byte, also after a JSON round trip', () => {
    for (const [, scene] of scenes) {
      const copy = JSON.parse(JSON.stringify(scene)) as Scene;
      expect(compile(copy)).toEqual(compile(scene));
      expect(shadertoySource(copy)).toBe(shadertoySource(scene));
    }
  });

  it('each element block starts with #line 1 <index + 1>, and lineMap names its node', () => {
    // The loop holds each element's step inline; its inside and edge distance are calls.
    const scene = HAND_MADE_SCENES['every-kind-cosine-edges-clip'];
    const p = compile(scene);
    const lines = p.source.split('\n');
    scene.elements.forEach((e, i) => {
      expect(p.lineMap[i + 1]).toBe(e.nodeId);
      // Each element has its blocks in the loop (step), after it (inside) and in the edge distance.
      const blocks = lines.flatMap((l, k) => (l === `#line 1 ${i + 1}` ? [lines[k + 1]] : []));
      expect(blocks).toHaveLength(3);
      expect(blocks[0]).toBe(`    { // ${e.kind}`);
      expect(blocks[1]).toContain(`if (${elementRecord(e).glsl.inside.name}(p,`);
      expect(blocks[2]).toContain(`${elementRecord(e).glsl.boundaryDistance.name}(p,`);
    });
    expect(Object.keys(p.lineMap)).toHaveLength(scene.elements.length);
  });
});

describe('limits are diagnostics, never driver errors', () => {
  const many = (n: number) => Array.from({ length: n }, (_, i) => reflection(`r${i}`, [i, 0], [1, 0]));

  it(`more than ${LIMITS.maxElements} elements: KF401, the extra ones are left out`, () => {
    const p = compile(makeScene(many(LIMITS.maxElements + 3)), { baked: true });
    expect(p.diagnostics.map((d) => d.code)).toContain('KF401');
    expect(Object.keys(p.lineMap)).toHaveLength(LIMITS.maxElements);
  });

  it(`uniform data beyond ${LIMITS.maxUniformVectors} vec4 rows: KF404 and a baked program instead`, () => {
    const rowsFor = (n: number) => {
      const p = compile(makeScene(many(n)), { baked: false });
      return FRAME_UNIFORMS.length + p.uniforms.reduce((r, u) => r + uniformRows(u), 0);
    };
    const fits = LIMITS.maxUniformVectors - rowsFor(1) + 1; // one reflection is one row
    const ok = compile(makeScene(many(fits)));
    expect(ok.diagnostics).toEqual([]);
    expect(rowsFor(fits)).toBe(LIMITS.maxUniformVectors);
    const over = compile(makeScene(many(fits + 1)));
    expect(over.diagnostics.map((d) => d.code)).toEqual(['KF404']);
    expect(over.uniforms).toEqual([]);
    expect(over.source).not.toMatch(/^uniform vec4 u_el\[/m);
    expect(over.source).toBe(compile(makeScene(many(fits + 1)), { baked: true }).source);
  });
});

describe('literals', () => {
  it('read back as the same number and always as a float', () => {
    expect([1, -0, 0.1, 1e-7, 1e21, -2.5].map(floatLiteral)).toEqual([
      '1.0',
      '0.0',
      '0.1',
      '1e-7',
      '1e+21',
      '-2.5',
    ]);
    expect(() => floatLiteral(Number.NaN)).toThrow();
    fc.assert(
      fc.property(fc.double({ noNaN: true, noDefaultInfinity: true }), (x) => {
        // Within float32's range a literal reads back exactly; beyond it, it is clamped (KF405 says so).
        const held = Math.max(-FLOAT32_MAX, Math.min(FLOAT32_MAX, x));
        expect(Number(floatLiteral(x))).toBe(held === 0 ? 0 : held);
        expect(floatLiteral(x)).toMatch(/[.e]/);
      }),
      { seed: 42, numRuns: 300 },
    );
  });

  it('never writes ∞: a derived value beyond float32 (r² of a huge radius) becomes ±FLOAT32_MAX', () => {
    expect(floatLiteral(Number.POSITIVE_INFINITY)).toBe(floatLiteral(FLOAT32_MAX));
    expect(floatLiteral(-1e300)).toBe(floatLiteral(-FLOAT32_MAX));
    const huge: SceneElement = { kind: 'inversion', nodeId: 'i', c: [0, 0], r: 1e300 };
    const scene: Scene = {
      ...HAND_MADE_SCENES['rose-cosine'],
      elements: [huge],
    };
    const program = compile(scene);
    expect(program.uniforms.every((u) => u.value.every(Number.isFinite))).toBe(true);
    expect(program.diagnostics.map((d) => d.code)).toContain('KF405');
    expect(compile(scene, { baked: true }).source).not.toMatch(/Infinity/);
  });

  it('KF405 also watches what is packed (r² of a radius within range) and a measure colouring’s scale', () => {
    const inversionScene = makeScene([{ kind: 'inversion', nodeId: 'i', c: [0, 0], r: 1e10 }]);
    expect(compile(inversionScene).diagnostics.map((d) => d.code)).toContain('KF405');
    const scaled = makeScene(TRIANGLE_333, {
      coloring: { ...measureColoring('x'), scale: 1e30 } as Coloring,
    });
    expect(compile(scaled).diagnostics.map((d) => d.code)).toContain('KF405');
    expect(compile(makeScene(TRIANGLE_333, { coloring: measureColoring('x') })).diagnostics).toEqual([]);
  });
});

describe('Shadertoy version', () => {
  it('is a mainImage with every value baked, the graph view and its samples, no #version/uniforms', () => {
    const scene = { ...HAND_MADE_SCENES['rose-cosine'], samples: 6 };
    const src = shadertoySource(scene);
    expect(src).toContain('void mainImage(out vec4 fragColor, in vec2 fragCoord) {');
    expect(src).toContain('for (int k = 0; k < 6; ++k)');
    expect(src).toContain('iResolution');
    expect(src).toContain('toSrgb(');
    expect(src).not.toMatch(/#version|#line|^uniform/m);
    expect(src).toContain(`vec3 view = vec3(0.0, 0.0, ${scene.view.scale.toFixed(1)});`);
  });
});
