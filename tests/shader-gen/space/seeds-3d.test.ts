/**
 * The GLSL seed distances (shader-gen/space/seeds-3d.ts): chosen by the seed's kind when the program
 * is generated, and each with a single exit. Early returns in these functions, inlined at every call
 * site by a software WebGL (SwiftShader), made the Fig. 37 program take minutes to compile
 * (docs/math-3d.md "Mirror material"); `npm run bench` times the first draws.
 */
import { describe, expect, it } from 'vitest';
import { compile3d } from '../../../shader-gen/space/compile-3d.ts';
import { seedDistanceCall, seedGlslFunctions } from '../../../shader-gen/space/seeds-3d.ts';
import { exampleScenes3d } from './scenes-3d.ts';

const examples = exampleScenes3d();
/** One example per seed kind: spheres, a box, a tile, a formula solid. */
const BY_KIND = {
  sphere: 'fig37-indras-bubbles-mirror',
  box: 'fig24-orbit-of-a-cube',
  tile: 'fig25-cube-type-sphairahedron',
  formula: 'formula-tilted-torus',
} as const;
const seedsOf = (kind: keyof typeof BY_KIND) => examples[BY_KIND[kind]]!.seeds;

describe('GLSL seed distances', () => {
  it('has an example of every seed kind', () => {
    for (const kind of Object.keys(BY_KIND) as (keyof typeof BY_KIND)[])
      expect(seedsOf(kind).some((s) => s.kind === kind)).toBe(true);
  });

  it('gives every seed distance function exactly one return (no early exit)', () => {
    const all = Object.keys(BY_KIND).flatMap((k) => seedGlslFunctions(seedsOf(k as keyof typeof BY_KIND)));
    expect(all.length).toBeGreaterThanOrEqual(4);
    for (const f of all) expect(f.code.match(/\breturn\b/g)?.length, f.name).toBe(1);
  });

  it('calls the function of the seed’s own kind, and emits only the functions the scene uses', () => {
    const sphere = seedsOf('sphere')[0]!;
    const box = seedsOf('box').find((s) => s.kind === 'box')!;
    expect(seedDistanceCall(sphere, 0, ['a', 'b'])).toBe('sphereSeedDistance(p, a)');
    expect(seedDistanceCall(box, 0, ['a', 'b'])).toBe('boxSeedDistance(p, a, b)');
    const names = seedGlslFunctions(seedsOf('sphere')).map((f) => f.name);
    expect(names).toEqual(['sphereSeedDistance']);
    const source = compile3d(examples[BY_KIND.sphere]!, { variant: 'probe' }).source;
    expect(source).not.toContain('boxSeedDistance');
  });
});
