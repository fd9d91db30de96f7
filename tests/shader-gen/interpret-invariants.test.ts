/**
 * Mathematical invariants of the IIS through `interpret` (a black box), on hand-made scenes and on
 * every example graph in examples/ (globbed at test time, so new examples are covered):
 *  - an escaped point ends in the tile (no element's inside holds its final point);
 *  - depth is 0 exactly when the start point is in the tile;
 *  - in a kaleidoscope (reflection group), applying one generating mirror changes depth by ±1;
 *  - the *2222 rectangle gives depth = |⌊x/a⌋| + |⌊y/b⌋|.
 */
import { readdirSync, readFileSync } from 'node:fs';
import { join } from 'node:path';
import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import type { DiskRegion, Scene, SceneElement } from '../../nodes/core/scene.ts';
import type { Vec2 } from '../../nodes/core/values.ts';
import { invertPoint, reflectPoint } from '../../nodes/geometry/circle.ts';
import { evaluateGraph } from '../../nodes/graph/evaluate.ts';
import { parseDocumentText } from '../../nodes/graph/load.ts';
import { registry } from '../../nodes/types/index.ts';
import { ELEMENTS } from '../../shader-gen/elements/index.ts';
import { interpret } from '../../shader-gen/interpret.ts';
import { rectangle, scene } from './interpret-scenes.ts';

const EXAMPLES_DIR = join(import.meta.dirname, '../../examples');

const inDisk = (R: DiskRegion, p: Vec2) => {
  const d2 = (p[0] - R.c[0]) ** 2 + (p[1] - R.c[1]) ** 2;
  return R.outside ? d2 > R.r * R.r : d2 < R.r * R.r;
};

/** The inside of an element, written from docs/math.md independently of shader-gen (other kinds: their own test). */
function inside(e: SceneElement, p: Vec2): boolean {
  switch (e.kind) {
    case 'inversion':
      return (p[0] - e.c[0]) ** 2 + (p[1] - e.c[1]) ** 2 < e.r * e.r;
    case 'reflection':
      return (p[0] - e.q[0]) * e.n[0] + (p[1] - e.q[1]) * e.n[1] < 0;
    case 'mobius':
    case 'loxodromic':
      return inDisk(e.a, p) || inDisk(e.b, p);
    default:
      return (ELEMENTS[e.kind].cpu.inside as (e: SceneElement, x: number, y: number) => boolean)(
        e,
        p[0],
        p[1],
      );
  }
}

type Mirror = Extract<SceneElement, { kind: 'inversion' | 'reflection' }>;
const isMirror = (e: SceneElement): e is Mirror => e.kind === 'inversion' || e.kind === 'reflection';
const mirrorImage = (m: Mirror, p: Vec2): Vec2 | null =>
  m.kind === 'inversion' ? invertPoint(m, p) : reflectPoint(m.q, m.n, p);
const mirrorDistance = (m: Mirror, p: Vec2) =>
  m.kind === 'inversion'
    ? Math.abs(Math.hypot(p[0] - m.c[0], p[1] - m.c[1]) - m.r)
    : Math.abs((p[0] - m.q[0]) * m.n[0] + (p[1] - m.q[1]) * m.n[1]);

type IisScene = Pick<Scene, 'elements' | 'maxIterations'>;

/** Checks the tile invariants at p; returns the result. */
function checkTile(s: IisScene, p: Vec2) {
  const r = interpret(s, p);
  const startInTile = !s.elements.some((e) => inside(e, p));
  expect(
    r.depth === 0,
    `depth ${r.depth} at (${p}) but start ${startInTile ? 'in' : 'not in'} the tile`,
  ).toBe(startInTile);
  if (r.depth === 0) expect(r.escaped).toBe(true);
  if (r.escaped) {
    expect(Number.isFinite(r.final[0]) && Number.isFinite(r.final[1])).toBe(true);
    const holder = s.elements.find((e) => inside(e, r.final));
    expect(
      holder,
      `escaped at (${r.final}) from (${p}) but inside element of ${holder?.nodeId}`,
    ).toBeUndefined();
  } else {
    expect(r.depth).toBeGreaterThanOrEqual(s.maxIterations);
  }
  return r;
}

/**
 * Applies a random generating mirror to p and checks |Δdepth| = 1. Points within `eps` of a mirror
 * (before or after) and points that do not escape are skipped. Returns whether it was checked.
 */
function checkMirrorStep(s: IisScene, p: Vec2, which: number, eps: number): boolean {
  const mirrors = s.elements as readonly Mirror[];
  const m = mirrors[which % mirrors.length];
  const q = mirrorImage(m, p);
  if (!q || !Number.isFinite(q[0]) || !Number.isFinite(q[1])) return false;
  if (mirrors.some((x) => mirrorDistance(x, p) < eps || mirrorDistance(x, q) < eps)) return false;
  const a = interpret(s, p);
  const b = interpret(s, q);
  if (!a.escaped || !b.escaped) return false;
  expect(
    Math.abs(a.depth - b.depth),
    `mirror ${which % mirrors.length} maps (${p}) depth ${a.depth} to (${q}) depth ${b.depth}`,
  ).toBe(1);
  return true;
}

/** Uniform in [−1, 1] (fast-check's usual bias towards 0 and bounds would put points on the mirrors). */
const uniform = fc.noBias(fc.integer({ min: -1_000_000_000, max: 1_000_000_000 })).map((k) => k / 1e9);

/** Random points in the square of half-size `half` around `center` (fixed seed). */
const pointsIn = (center: Vec2, half: number) =>
  fc.tuple(uniform, uniform).map(([u, v]): Vec2 => [center[0] + u * half, center[1] + v * half]);

function kaleidoscopeScene(p: number, q: number, r: number, size = 1): Scene {
  const ev = evaluateGraph(
    {
      format: 'kleinflow',
      version: 1,
      meta: {},
      nodes: [
        { id: 'k', type: 'kaleidoscope', position: [0, 0], params: { p, q, r, size } },
        { id: 'out', type: 'render', position: [0, 0], params: { maxIterations: 400 } },
      ],
      edges: [{ id: 'e', from: { node: 'k', port: 'elements' }, to: { node: 'out', port: 'elements' } }],
      view: { center: [0, 0], scale: 4 },
    },
    registry,
  );
  expect(ev.scene.elements).toHaveLength(3);
  return ev.scene;
}

const RUNS = { seed: 42, numRuns: 150 } as const;

describe('tile invariants on hand-made scenes', () => {
  const cases: [string, IisScene, Vec2, number][] = [
    ['(7, 2, 3) hyperbolic', kaleidoscopeScene(7, 2, 3), [0, 0], 1.3],
    ['(3, ∞, 3) ideal vertex', kaleidoscopeScene(3, 0, 3), [0, 0], 1.3],
    ['(4, 2, 3) spherical', kaleidoscopeScene(4, 2, 3), [0, 0], 3],
    ['(6, 2, 3) Euclidean', kaleidoscopeScene(6, 2, 3, 0.7), [0, 0], 4],
    ['*2222 rectangle', scene(rectangle(1.5, 0.7), 400), [0.4, 0.2], 6],
  ];
  it.each(cases)('%s: final points in the tile, depth 0 exactly in the tile', (_name, s, c, half) => {
    fc.assert(
      fc.property(pointsIn(c, half), (p) => void checkTile(s, p)),
      RUNS,
    );
  });

  it.each(cases)('%s: one mirror changes depth by exactly ±1', (_name, s, c, half) => {
    let checked = 0;
    fc.assert(
      fc.property(pointsIn(c, half), fc.nat(), (p, k) => {
        if (checkMirrorStep(s, p, k, 1e-7)) checked++;
      }),
      RUNS,
    );
    expect(checked).toBeGreaterThan(RUNS.numRuns / 2);
  });

  it('a Schottky pair of two-circle generators (Möbius elements)', () => {
    const ev = evaluateGraph(
      {
        format: 'kleinflow',
        version: 1,
        meta: {},
        nodes: [
          {
            id: 'g',
            type: 'mobius',
            position: [0, 0],
            params: { c1: { c: [-2, 0], r: 0.8 }, c2: { c: [2, 0], r: 0.8 } },
          },
          {
            id: 'h',
            type: 'mobius',
            position: [0, 0],
            params: { c1: { c: [0, -2], r: 0.8 }, c2: { c: [0, 2], r: 0.8 } },
          },
          { id: 'n', type: 'mobius', position: [0, 0], params: {} },
          { id: 'out', type: 'render', position: [0, 0], params: { maxIterations: 300 } },
        ],
        edges: [
          { id: 'e1', from: { node: 'g', port: 'element' }, to: { node: 'out', port: 'elements' } },
          { id: 'e2', from: { node: 'h', port: 'element' }, to: { node: 'out', port: 'elements' } },
        ],
        view: { center: [0, 0], scale: 4 },
      },
      registry,
    );
    expect(ev.scene.elements.map((e) => e.kind)).toEqual(['mobius', 'mobius']);
    fc.assert(
      fc.property(pointsIn([0, 0], 3), (p) => void checkTile(ev.scene, p)),
      RUNS,
    );
    // the nested default generator alone
    const nested = ev.nodes.get('n')!.outputs!.element as SceneElement[];
    fc.assert(
      fc.property(pointsIn([0, 0], 3), (p) => void checkTile(scene(nested, 300), p)),
      RUNS,
    );
  });
});

describe('the *2222 closed form', () => {
  it('four mirrors of [0, a] × [0, b] give depth = |⌊x/a⌋| + |⌊y/b⌋|', () => {
    const a = 1.25;
    const b = 0.5;
    const s = scene(rectangle(a, b), 1000);
    fc.assert(
      fc.property(uniform, uniform, (u, v) => {
        const [x, y] = [20 * u, 20 * v];
        const near = (t: number) => Math.abs(t - Math.round(t)) < 1e-9;
        fc.pre(!near(x / a) && !near(y / b));
        const r = interpret(s, [x, y]);
        expect(r.escaped).toBe(true);
        expect(r.depth).toBe(Math.abs(Math.floor(x / a)) + Math.abs(Math.floor(y / b)));
        expect(r.final[0]).toBeGreaterThanOrEqual(0);
        expect(r.final[0]).toBeLessThanOrEqual(a);
        expect(r.scale).toBe(1);
      }),
      { seed: 42, numRuns: 400 },
    );
  });
});

describe('invariants on every example graph', () => {
  const files = readdirSync(EXAMPLES_DIR)
    .filter((f) => f.endsWith('.kleinflow.json'))
    .sort();

  it('finds the examples', () => {
    expect(files.length).toBeGreaterThan(0);
  });

  it.each(files)('%s', (file) => {
    const loaded = parseDocumentText(readFileSync(join(EXAMPLES_DIR, file), 'utf8'), registry);
    if (!loaded.ok)
      throw new Error(
        `${file} does not load: ${loaded.diagnostics.map((d) => `${d.path}: ${d.message}`).join('; ')}`,
      );
    const ev = evaluateGraph(loaded.doc, registry);
    const s = ev.scene;
    expect(s.renderNodeId, `${file} has no render node`).not.toBeNull();
    expect(ev.diagnostics.filter((d) => d.severity === 'error')).toEqual([]);
    expect(s.elements.length).toBeGreaterThan(0);
    const { center, scale } = s.view;
    const half = scale * 0.75; // a 3:2 canvas and a little more vertically
    fc.assert(
      fc.property(pointsIn(center, half), (p) => void checkTile(s, p)),
      { seed: 42, numRuns: 200 },
    );

    // A kaleidoscope: every element is a mirror from one node of the Kaleidoscopes category.
    const sources = new Set(s.elements.map((e) => e.nodeId));
    const kaleidoscope =
      s.elements.length > 0 &&
      s.elements.every(isMirror) &&
      sources.size === 1 &&
      ev.analysis.nodes.get([...sources][0])?.def?.category === 'Kaleidoscopes';
    if (!kaleidoscope) return;
    let checked = 0;
    fc.assert(
      fc.property(pointsIn(center, half), fc.nat(), (p, k) => {
        if (checkMirrorStep(s, p, k, 1e-7 * scale)) checked++;
      }),
      { seed: 42, numRuns: 200 },
    );
    expect(checked).toBeGreaterThan(50);
  });
});
