/**
 * Every diagnostic that nodes/graph can produce is produced here by a minimal scenario. The list of
 * keys is read from the source at test time, so a new diag('…') call in nodes/graph without a
 * scenario fails this test.
 */
import { readdirSync, readFileSync } from 'node:fs';
import { join } from 'node:path';
import { describe, expect, it } from 'vitest';
import { DIAGNOSTICS, type Diagnostic, type DiagnosticKey } from '../../../nodes/core/diagnostics.ts';
import { LIMITS } from '../../../nodes/core/scene.ts';
import { analyzeGraph } from '../../../nodes/graph/analyze.ts';
import { evaluateGraph } from '../../../nodes/graph/evaluate.ts';
import { groupNodes } from '../../../nodes/graph/grouping.ts';
import { loadDocument, parseDocumentText } from '../../../nodes/graph/load.ts';
import { registry } from '../../../nodes/types/index.ts';
import { doc, edge, node } from '../support/doc.ts';
import { testRegistry } from './fixtures.ts';
import { EQUILATERAL, triangleDoc } from './mirror-fixtures.ts';

const GRAPH_DIR = join(import.meta.dirname, '../../../nodes/graph');

/** Keys used as diag('key', …) in nodes/graph/*.ts. */
function keysUsedInGraph(): Set<string> {
  const keys = new Set<string>();
  for (const f of readdirSync(GRAPH_DIR).filter((f) => f.endsWith('.ts'))) {
    const src = readFileSync(join(GRAPH_DIR, f), 'utf8');
    for (const m of src.matchAll(/\bdiag\(\s*'(\w+)'/g)) keys.add(m[1]);
  }
  return keys;
}

const loadFails = (value: unknown) => {
  const r = loadDocument(value, registry);
  return r.ok ? [] : r.diagnostics;
};
const textFails = (text: string) => {
  const r = parseDocumentText(text, registry);
  return r.ok ? [] : r.diagnostics;
};
const base = () => doc([node('p', 'point'), node('c', 'circle'), node('out', 'render')]);

const SCENARIOS: Partial<Record<DiagnosticKey, () => readonly Diagnostic[]>> = {
  notJson: () => textFails('{nope'),
  schema: () => loadFails({ ...base(), view: { center: [0, 0], scale: 0 } }),
  wrongFormat: () => loadFails({ ...base(), format: 'svg' }),
  futureVersion: () => loadFails({ ...base(), version: 99 }),
  tooManyNodes: () =>
    loadFails({
      ...base(),
      nodes: Array.from({ length: LIMITS.maxNodes + 1 }, (_, i) => node(`n${i}`, 'point')),
    }),
  duplicateNodeId: () => analyzeGraph(doc([node('a', 'point'), node('a', 'point')]), registry).diagnostics,
  duplicateEdgeId: () =>
    analyzeGraph(
      doc(base().nodes, [edge('e', 'p.point', 'c.center'), edge('e', 'p.point', 'c.center')]),
      registry,
    ).diagnostics,
  unknownNodeType: () => analyzeGraph(doc([node('a', 'teleporter')]), registry).diagnostics,
  danglingEdge: () =>
    analyzeGraph(doc(base().nodes, [edge('e', 'nope.point', 'c.center')]), registry).diagnostics,
  unknownPort: () => analyzeGraph(doc(base().nodes, [edge('e', 'p.nope', 'c.center')]), registry).diagnostics,
  typeMismatch: () =>
    analyzeGraph(doc(base().nodes, [edge('e', 'p.point', 'out.clip')]), registry).diagnostics,
  multipleEdges: () =>
    analyzeGraph(
      doc(
        [...base().nodes, node('q', 'point')],
        [edge('e1', 'p.point', 'c.center'), edge('e2', 'q.point', 'c.center')],
      ),
      registry,
    ).diagnostics,
  cycle: () =>
    analyzeGraph(
      doc(
        [node('a', 'number'), node('b', 'number')],
        [edge('e1', 'a.value', 'b.value'), edge('e2', 'b.value', 'a.value')],
      ),
      registry,
    ).diagnostics,
  selfEdge: () =>
    analyzeGraph(doc([node('a', 'number')], [edge('e1', 'a.value', 'a.value')]), registry).diagnostics,
  noRender: () => evaluateGraph(doc([node('a', 'point')]), registry).diagnostics,
  manyRenders: () => evaluateGraph(doc([node('r1', 'render'), node('r2', 'render')]), registry).diagnostics,
  badParam: () => evaluateGraph(doc([node('c', 'circle', { radius: 'big' })]), registry).diagnostics,
  upstreamMissing: () =>
    evaluateGraph(
      doc([node('c', 'circle', { radius: -1 }), node('i', 'inversion')], [edge('e', 'c.circle', 'i.circle')]),
      registry,
    ).diagnostics,
  inputMuted: () =>
    evaluateGraph(
      doc(
        [{ ...node('c', 'circle'), muted: true }, node('i', 'inversion')],
        [edge('e', 'c.circle', 'i.circle')],
      ),
      registry,
    ).diagnostics,
  noPortValue: () =>
    evaluateGraph(
      doc(
        [node('k', 'kaleidoscope', { p: 3, q: 3, r: 3 }), node('out', 'render')],
        [edge('e', 'k.boundary', 'out.clip')],
      ),
      registry,
    ).diagnostics,
  keptSides: () => evaluateGraph(triangleDoc(EQUILATERAL, ['AB', 'AC', 'BC']), registry).diagnostics,
  mirrorAngle: () =>
    evaluateGraph(
      triangleDoc(
        [
          [0, 0],
          [1, 0],
          [0.3, 1],
        ],
        ['AB', 'BC', 'CA'],
      ),
      registry,
    ).diagnostics,
  groupPortMissing: () => {
    const g = groupNodes(doc(base().nodes, [edge('e', 'p.point', 'c.center')]), ['p'], 'g');
    const body = g.nodes.find((n) => n.id === 'g')!.group!;
    const broken = {
      ...body,
      outputs: body.outputs.map((o) => ({ ...o, from: { ...o.from, node: 'gone' } })),
    };
    return evaluateGraph(
      { ...g, nodes: g.nodes.map((n) => (n.group ? { ...n, group: broken } : n)) },
      registry,
    ).diagnostics;
  },
  nodeVersion: () => evaluateGraph(doc([{ ...node('p', 'point'), version: 99 }]), registry).diagnostics,
  nodeThrew: () => evaluateGraph(doc([node('t', 'test-throws')]), testRegistry).diagnostics,
  nonFinite: () => evaluateGraph(doc([node('t', 'test-nan')]), testRegistry).diagnostics,
};

describe('diagnostic coverage of nodes/graph', () => {
  const used = [...keysUsedInGraph()].sort();

  it('finds the diag() calls of nodes/graph', () => {
    expect(used.length).toBeGreaterThan(15);
    for (const k of used) expect(Object.hasOwn(DIAGNOSTICS, k)).toBe(true);
  });

  it.each(used)('%s is produced by a scenario', (key) => {
    const scenario = SCENARIOS[key as DiagnosticKey];
    expect(scenario, `add a scenario for diag('${key}') to this file`).toBeDefined();
    const code = DIAGNOSTICS[key as DiagnosticKey].code;
    expect(scenario!().map((d) => d.code)).toContain(code);
  });

  it('codes are unique and numbered KFnnn', () => {
    const codes = Object.values(DIAGNOSTICS).map((e) => e.code);
    expect(new Set(codes).size).toBe(codes.length);
    for (const c of codes) expect(c).toMatch(/^KF\d{3}$/);
  });
});
