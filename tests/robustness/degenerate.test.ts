/**
 * Degenerate geometry: coincident and collinear points, zero and negative radii, circles through
 * each other's centres, identical circles, impossible (p, q, r), singular matrices… Each one is
 * wired into a render node and run through evaluate and compile. The node must say what is wrong
 * (a diagnostic with its id), nothing may throw (no KF305 "internal error"), and no NaN or ∞ may
 * reach the scene or the uniforms. Then every registered type gets extreme numbers in every
 * number and point input, one at a time.
 */
import { describe, expect, it } from 'vitest';
import type { GraphDoc, GraphEdge, GraphNode } from '../../nodes/graph/document.ts';
import { registry } from '../../nodes/types/index.ts';
import { checkPipeline, type PipelineReport } from '../fuzz/pipeline-check.ts';
import { doc, node } from '../nodes/support/doc.ts';

const circle = (x: number, y: number, r: number) => ({ c: [x, y], r });
const line = (ax: number, ay: number, bx: number, by: number) => ({ a: [ax, ay], b: [bx, by] });

/**
 * A node of `type` with `params`, each output that can feed the render node wired into it
 * (elements → elements, a circle → clip), so its result goes all the way to the compiled shader.
 */
function wiredDoc(type: string, params: Record<string, unknown>): GraphDoc {
  const def = registry.get(type)!;
  const nodes: GraphNode[] = [node('n', type, params), node('out', 'render')];
  const edges: GraphEdge[] = [];
  for (const [port, spec] of Object.entries(def.outputs)) {
    const to =
      spec.type === 'element'
        ? 'elements'
        : spec.type === 'circle' && !edges.some((e) => e.to.port === 'clip')
          ? 'clip'
          : null;
    if (to) edges.push({ id: `e${edges.length}`, from: { node: 'n', port }, to: { node: 'out', port: to } });
  }
  return doc(nodes, edges);
}

function run(type: string, params: Record<string, unknown>): PipelineReport {
  const report = checkPipeline({ value: wiredDoc(type, params) });
  expect(report.problems, `${type} ${JSON.stringify(params)}`).toEqual([]);
  const internal = report.diagnostics.filter((d) => d.code === 'KF305');
  expect(internal, `${type} ${JSON.stringify(params)} threw inside`).toEqual([]);
  return report;
}

/** The node itself reports the problem: an error or a warning carrying its id. */
function expectReported(type: string, params: Record<string, unknown>): void {
  const report = run(type, params);
  const own = report.diagnostics.filter((d) => d.nodeId === 'n' && d.severity !== 'info');
  expect(own.length, `${type} ${JSON.stringify(params)}: no diagnostic on the node`).toBeGreaterThan(0);
  for (const d of own) expect(d.message.length).toBeGreaterThan(5);
}

describe('degenerate constructions are reported on their node', () => {
  const cases: [string, string, Record<string, unknown>][] = [
    ['line through one point twice', 'line', { a: [0.5, 0.5], b: [0.5, 0.5] }],
    ['circle with radius 0', 'circle', { radius: 0 }],
    ['circle with radius −1', 'circle', { radius: -1 }],
    ['circle through three coincident points', 'circle-3pt', { a: [1, 1], b: [1, 1], c: [1, 1] }],
    ['circle through two coincident points', 'circle-3pt', { a: [0, 0], b: [0, 0], c: [1, 0] }],
    ['circle through three collinear points', 'circle-3pt', { a: [-1, 0], b: [0, 0], c: [1, 0] }],
    ['circle whose rim point is its centre', 'circle-center-point', { center: [0, 0], through: [0, 0] }],
    ['perpendicular bisector of one point', 'perpendicular-bisector', { a: [1, 2], b: [1, 2] }],
    ['parallel to a degenerate line', 'parallel-line', { line: line(0, 0, 0, 0) }],
    ['perpendicular to a degenerate line', 'perpendicular-line', { line: line(0, 0, 0, 0) }],
    ['intersection of parallel lines', 'intersect-lines', { l1: line(0, 0, 1, 0), l2: line(0, 1, 1, 1) }],
    ['intersection of a line with itself', 'intersect-lines', { l1: line(0, 0, 1, 0), l2: line(0, 0, 1, 0) }],
    [
      'intersection with a degenerate line',
      'intersect-lines',
      { l1: line(0, 0, 0, 0), l2: line(0, 1, 1, 1) },
    ],
    [
      'line missing the circle',
      'intersect-line-circle',
      { line: line(-2, 3, 2, 3), circle: circle(0, 0, 1) },
    ],
    [
      'degenerate line and a circle',
      'intersect-line-circle',
      { line: line(0, 0, 0, 0), circle: circle(0, 0, 1) },
    ],
    ['concentric circles meet nowhere', 'intersect-circles', { c1: circle(0, 0, 1), c2: circle(0, 0, 2) }],
    ['identical circles', 'intersect-circles', { c1: circle(0, 0, 1), c2: circle(0, 0, 1) }],
    ['disjoint circles', 'intersect-circles', { c1: circle(0, 0, 1), c2: circle(5, 0, 1) }],
    ['inverting the centre', 'invert-point', { circle: circle(0, 0, 1), point: [0, 0] }],
    ['inverting in a zero circle', 'invert-point', { circle: circle(0, 0, 0), point: [1, 0] }],
    ['reflecting in a degenerate line', 'reflect-point', { line: line(1, 1, 1, 1), point: [0, 0] }],
    ['angle with a coincident arm', 'angle', { a: [0, 0], b: [0, 0], c: [0, 1] }],
    ['inversion in a zero circle', 'inversion', { circle: circle(0, 0, 0) }],
    ['inversion in a negative circle', 'inversion', { circle: circle(0, 0, -2) }],
    ['reflection in a degenerate line', 'reflection', { line: line(0, 0, 0, 0) }],
    ['Möbius: C1 passes through the centre of C2', 'mobius', { c1: circle(0, 0, 1), c2: circle(1, 0, 0.5) }],
    ['Möbius: identical circles', 'mobius', { c1: circle(0, 0, 1), c2: circle(0, 0, 1) }],
    ['Möbius: zero radius', 'mobius', { c1: circle(0, 0, 0), c2: circle(1, 0, 1) }],
    ['loxodromic: P on the line of centres', 'loxodromic', { control: [0.6, 0] }],
    ['loxodromic: P on C1', 'loxodromic', { control: [0, 1] }],
    ['loxodromic: P on C2', 'loxodromic', { control: [0.3, 2] }],
    ['loxodromic: concentric circles', 'loxodromic', { c1: circle(0, 0, 1), c2: circle(0, 0, 2) }],
    ['loxodromic: identical circles', 'loxodromic', { c1: circle(0, 0, 1), c2: circle(0, 0, 1) }],
    [
      'Möbius matrix with determinant 0',
      'mobius-matrix',
      { a_re: 1, a_im: 0, b_re: 1, b_im: 0, c_re: 1, c_im: 0, d_re: 1, d_im: 0 },
    ],
    [
      'Möbius matrix of zeros',
      'mobius-matrix',
      { a_re: 0, a_im: 0, b_re: 0, b_im: 0, c_re: 0, c_im: 0, d_re: 0, d_im: 0 },
    ],
    ['translation by period 0', 'translation', { period: 0 }],
    ['glide reflection by period 0', 'glide-reflection', { period: 0 }],
    ['parallel mirrors at distance 0', 'parallel-mirrors', { period: 0 }],
    ['rotation of order 2.5', 'rotation', { order: 2.5 }],
    ['rotation of order 1', 'rotation', { order: 1 }],
    ['spiral similarity with r1 = r2', 'spiral-similarity', { r1: 0.5, r2: 0.5 }],
    ['spiral similarity with r1 > r2', 'spiral-similarity', { r1: 0.8, r2: 0.5 }],
    ['spiral similarity with r1 = 0', 'spiral-similarity', { r1: 0, r2: 0.5 }],
    ['kaleidoscope with q = 1', 'kaleidoscope', { q: 1 }],
    ['kaleidoscope with p = 0', 'kaleidoscope', { p: 0 }],
    ['kaleidoscope with non-integer p', 'kaleidoscope', { p: 2.5 }],
    ['kaleidoscope with huge p', 'kaleidoscope', { p: 1e308 }],
    ['kaleidoscope with size 0', 'kaleidoscope', { p: 3, q: 3, r: 3, size: 0 }],
    ['k-mirror with k = 0', 'k-mirror', { k: 0 }],
    ['k-mirror with non-integer k', 'k-mirror', { k: 2.5 }],
    ['rectangle of width 0', 'rectangle-kaleidoscope', { width: 0 }],
    ['hyperbolic polygon that is spherical', 'hyperbolic-polygon', { n: 3, q: 2 }],
    ['hyperbolic polygon that is Euclidean', 'hyperbolic-polygon', { n: 4, q: 2 }],
    ['hyperbolic polygon with n = 2', 'hyperbolic-polygon', { n: 2 }],
  ];
  for (const [title, type, params] of cases) {
    it(title, () => {
      expect(registry.get(type), `node type ${type} is registered`).toBeDefined();
      expectReported(type, params);
    });
  }
});

describe('special but valid configurations stay finite', () => {
  const cases: [string, string, Record<string, unknown>][] = [
    ['Möbius with tangent circles (parabolic)', 'mobius', { c1: circle(0, 0, 1), c2: circle(2, 0, 1) }],
    ['Möbius with internally tangent circles', 'mobius', { c1: circle(0, 0, 1), c2: circle(-0.5, 0, 1.5) }],
    ['Möbius with concentric circles', 'mobius', { c1: circle(0, 0, 1), c2: circle(0, 0, 2) }],
    ['Möbius with circles far apart', 'mobius', { c1: circle(-1e6, 0, 1), c2: circle(1e6, 0, 1) }],
    ['Möbius with tiny circles', 'mobius', { c1: circle(0, 0, 1e-150), c2: circle(1e-150, 0, 2e-150) }],
    [
      'line tangent to the circle',
      'intersect-line-circle',
      { line: line(-2, 1, 2, 1), circle: circle(0, 0, 1) },
    ],
    ['tangent circles meet once', 'intersect-circles', { c1: circle(0, 0, 1), c2: circle(2, 0, 1) }],
    ['kaleidoscope with ideal vertices', 'kaleidoscope', { p: 2, q: 0, r: 0 }],
    ['kaleidoscope (2, 2, 0)', 'kaleidoscope', { p: 2, q: 2, r: 0 }],
    ['Euclidean kaleidoscope (3, 3, 3)', 'kaleidoscope', { p: 3, q: 3, r: 3 }],
    [
      'parabolic matrix',
      'mobius-matrix',
      { a_re: 1, a_im: 0, b_re: 1, b_im: 0, c_re: 0, c_im: 0, d_re: 1, d_im: 0 },
    ],
  ];
  for (const [title, type, params] of cases) {
    it(title, () => {
      expect(registry.get(type), `node type ${type} is registered`).toBeDefined();
      const report = run(type, params);
      for (const d of report.diagnostics.filter((x) => x.severity !== 'info'))
        expect(d.path || d.nodeId).toBeTruthy();
    });
  }
});

/** Values set into one number at a time; a point input gets them in x, then in y. */
const EXTREMES = [0, -1, 1e308, -1e308, 1e-300, 5e-324, 3.5e38] as const;

describe('every node type with an extreme number in one input at a time', () => {
  for (const def of registry.all) {
    it(def.type, () => {
      run(def.type, {}); // the defaults first
      for (const [name, spec] of Object.entries(def.inputs)) {
        const variants: unknown[] = [];
        if (spec.type === 'number') variants.push(...EXTREMES);
        if (spec.type === 'point') for (const v of EXTREMES) variants.push([v, 0], [0, v]);
        if (spec.type === 'circle')
          for (const v of EXTREMES) variants.push({ c: [v, 0], r: 1 }, { c: [0, 0], r: v });
        if (spec.type === 'line')
          for (const v of EXTREMES) variants.push({ a: [v, 0], b: [1, 1] }, { a: [0, 0], b: [0, v] });
        for (const value of variants) {
          const report = run(def.type, { [name]: value });
          // Refused values say so on the node: an error or warning carrying its id.
          for (const d of report.diagnostics.filter((x) => x.severity !== 'info'))
            expect(d.path || d.nodeId).toBeTruthy();
        }
      }
      for (const [name, spec] of Object.entries(def.params)) {
        if (spec.kind !== 'number') continue;
        for (const value of EXTREMES) run(def.type, { [name]: value });
      }
    });
  }
});
