/** Diagnostics of grouped documents as one level of groups shows them. */
import { describe, expect, it } from 'vitest';
import type { Diagnostic } from '../../../nodes/core/diagnostics.ts';
import type { GraphNode } from '../../../nodes/graph/document.ts';
import { diagnosticAtLevel } from '../../../nodes/graph/group-diagnostics.ts';
import { registry } from '../../../nodes/types/index.ts';
import { node } from '../support/doc.ts';

const group = (id: string, nodes: GraphNode[], label?: string): GraphNode => ({
  ...node(id, 'group'),
  ...(label ? { label } : {}),
  group: { nodes, edges: [], inputs: [], outputs: [] },
});

/** Outer group A holds inner group g2 (unlabelled) holding circle c; "g2/c" is c's flattened id. */
const nested = { nodes: [group('A', [group('g2', [node('c', 'circle')])], 'Outer'), node('out', 'render')] };
const origin = new Map([['g2/c', ['A', 'g2', 'c']]]);
const problem: Diagnostic = {
  code: 'KF301',
  severity: 'error',
  message: 'radius must be > 0',
  nodeId: 'g2/c',
  port: 'radius',
};

describe('diagnosticAtLevel', () => {
  it('goes on the group at each level, saying the way down to the node; on the node where it is', () => {
    expect(diagnosticAtLevel(problem, nested, origin, [], registry)).toEqual({
      code: 'KF301',
      severity: 'error',
      nodeId: 'A',
      message: 'in group ‘Outer’ → group ‘Group’ → node ‘Circle’: radius must be > 0',
    });
    expect(diagnosticAtLevel(problem, nested, origin, ['A'], registry)?.message).toBe(
      'in group ‘Group’ → node ‘Circle’: radius must be > 0',
    );
    expect(diagnosticAtLevel(problem, nested, origin, ['A', 'g2'], registry)).toEqual({
      ...problem,
      nodeId: 'c',
    });
  });

  it('is not shown at a level it is not in; one without a node belongs to the top level', () => {
    const onOut: Diagnostic = { ...problem, nodeId: 'out' };
    expect(diagnosticAtLevel(onOut, nested, origin, [], registry)).toBe(onOut);
    expect(diagnosticAtLevel(onOut, nested, origin, ['A'], registry)).toBeNull();
    const whole: Diagnostic = {
      code: 'KF401',
      severity: 'warning',
      message: 'no render',
      path: '(document)',
    };
    expect(diagnosticAtLevel(whole, nested, origin, [], registry)).toBe(whole);
    expect(diagnosticAtLevel(whole, nested, origin, ['A'], registry)).toBeNull();
  });
});
