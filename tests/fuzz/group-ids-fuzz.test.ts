/**
 * Fuzzing the two document faults of issue #24 (fixed seeds): node ids that repeat across groups,
 * inside one group or between a group and a plain node are each reported (KF201, naming both
 * places), never dropped silently; and ids and labels full of control characters (terminal
 * escapes, newlines, bidi overrides) go through the pipeline and come out of the CLI's message
 * formatting as one printable line.
 */
import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import type { GraphDoc, GraphNode } from '../../nodes/graph/document.ts';
import { groupNodes } from '../../nodes/graph/grouping.ts';
import { formatDiagnostic } from '../../src/cli/load-graph.ts';
import { doc, edge, node } from '../nodes/support/doc.ts';
import { checkPipeline } from './pipeline-check.ts';

const SEED = 24;

/** c → i → out with c and i grouped as g, and a second copy of the group as h (ids scoped apart). */
function twoGroups(): GraphDoc {
  const flat = doc(
    [node('c', 'circle', { radius: 0.5 }), node('i', 'inversion'), node('out', 'render')],
    [edge('e1', 'c.circle', 'i.circle'), edge('e2', 'i.element', 'out.elements')],
  );
  const grouped = groupNodes(flat, ['c', 'i'], 'g');
  const g = grouped.nodes.find((n) => n.id === 'g')!;
  return { ...grouped, nodes: [...grouped.nodes, { ...g, id: 'h' }] };
}

type Clash = { kind: 'top'; from: number } | { kind: 'inner'; group: number; from: number };

/** `d` with one node copied next to itself: a top-level node (maybe a group) or an inner node. */
function withClash(d: GraphDoc, clash: Clash, at: number): GraphDoc {
  const insert = <T>(list: readonly T[], item: T) => {
    const k = at % (list.length + 1);
    return [...list.slice(0, k), item, ...list.slice(k)];
  };
  if (clash.kind === 'top') return { ...d, nodes: insert(d.nodes, d.nodes[clash.from % d.nodes.length]) };
  const groups = d.nodes.filter((n) => n.group);
  const target = groups[clash.group % groups.length];
  const body = target.group!;
  const copied: GraphNode = body.nodes[clash.from % body.nodes.length];
  return {
    ...d,
    nodes: d.nodes.map((n) =>
      n === target ? { ...n, group: { ...body, nodes: insert(body.nodes, copied) } } : n,
    ),
  };
}

const clash: fc.Arbitrary<Clash> = fc.oneof(
  fc.record({ kind: fc.constant('top' as const), from: fc.nat(10) }),
  fc.record({ kind: fc.constant('inner' as const), group: fc.nat(3), from: fc.nat(10) }),
);

// biome-ignore lint/suspicious/noControlCharactersInRegex: the characters that must not be printed raw
const RAW_CONTROL = /[\u0000-\u001f\u007f-\u009f\u2028\u2029\u202a-\u202e\u2066-\u2069]/;

const hostileText = fc.string({
  unit: fc.constantFrom(
    '\u001b',
    '[2J',
    ']0;',
    '\u0007',
    '\n',
    '\r',
    '\u009b',
    '\u202e',
    '\u2028',
    'a',
    'b.json: ok',
  ),
  minLength: 1,
  maxLength: 12,
});

describe('duplicate ids in grouped documents', () => {
  it('every clash (across groups, inside a group, group beside node, nested) is a KF201 naming both places', () => {
    fc.assert(
      fc.property(clash, fc.nat(10), fc.boolean(), (c, at, nest) => {
        const base = nest ? groupNodes(twoGroups(), ['g', 'h'], 'outer') : twoGroups();
        const text = JSON.stringify(withClash(base, c, at));
        const report = checkPipeline({ text });
        expect(report.problems).toEqual([]);
        const said = report.diagnostics.filter((d) => d.code === 'KF201');
        expect(said).toHaveLength(1);
        expect(said[0].severity).toBe('error');
        expect(said[0].path).toMatch(/^nodes\[\d+\](\.group\.nodes\[\d+\])*\.id$/);
        expect(said[0].message).toMatch(/: nodes\[\d+\](\.group\.nodes\[\d+\])* already has it$/);
      }),
      { seed: SEED, numRuns: 300 },
    );
  }, 60_000);
});

describe('control characters in ids and labels', () => {
  it('pass through the pipeline and come out of the CLI formatting as one printable line', () => {
    fc.assert(
      fc.property(hostileText, hostileText, fc.boolean(), (id, label, grouped) => {
        const flat = doc(
          [
            { ...node(id, 'teleporter'), label },
            { ...node('c', 'circle', { radius: -1 }), label },
            node('out', 'render'),
          ],
          [edge('e1', `${id}.element`, 'out.elements')],
        );
        const d = grouped ? groupNodes(flat, [id, 'c'], 'g') : flat;
        const report = checkPipeline({ text: JSON.stringify(d) });
        expect(report.problems).toEqual([]);
        expect(report.diagnostics.length).toBeGreaterThan(0);
        for (const diagnostic of report.diagnostics) {
          const line = formatDiagnostic(diagnostic, d);
          expect(line).not.toMatch(RAW_CONTROL);
        }
      }),
      { seed: SEED, numRuns: 300 },
    );
  }, 60_000);
});
