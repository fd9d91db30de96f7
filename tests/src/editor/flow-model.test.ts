import { describe, expect, it } from 'vitest';
import { PORT_TYPE_INFO } from '../../../nodes/core/ports.ts';
import { emptyDocument, type GraphDoc } from '../../../nodes/graph/document.ts';
import { evaluateGraph } from '../../../nodes/graph/evaluate.ts';
import { registry } from '../../../nodes/types/index.ts';
import { diagnosticsByNode, toFlowEdges, toFlowNodes } from '../../../src/editor/flow-model.ts';

const doc: GraphDoc = {
  ...emptyDocument('t'),
  nodes: [
    { id: 'p', type: 'point', position: [0, 0], params: {} },
    { id: 'l', type: 'line', position: [300, 0], params: { b: [0, 0] } },
    { id: 'x', type: 'no-such-type', position: [600, 0], params: {} },
  ],
  edges: [
    { id: 'e1', from: { node: 'p', port: 'point' }, to: { node: 'l', port: 'a' } },
    { id: 'e2', from: { node: 'l', port: 'line' }, to: { node: 'x', port: 'in' } },
  ],
};

describe('document → React Flow', () => {
  const evaluation = evaluateGraph(doc, registry);
  const byNode = diagnosticsByNode(evaluation.diagnostics);
  const nodes = toFlowNodes(doc, registry, evaluation.nodes, byNode, new Set(['l']), null, new Map());

  it('makes one generic node per document node, with its type, connections and selection', () => {
    expect(nodes.map((n) => [n.id, n.type, n.position.x])).toEqual([
      ['p', 'kf', 0],
      ['l', 'kf', 300],
      ['x', 'kf', 600],
    ]);
    expect([...nodes[1].data.connected]).toEqual(['a']);
    expect(nodes[1].selected).toBe(true);
    expect(nodes[0].data.def?.type).toBe('point');
  });

  it('puts each diagnostic on its node: the degenerate line, the unknown type', () => {
    // a = (0, 0) from the point, b = (0, 0) inline: the line has no direction.
    expect(nodes[1].data.diagnostics.some((d) => d.severity === 'error')).toBe(true);
    expect(nodes[2].data.diagnostics.map((d) => d.code)).toContain('KF203');
    expect(nodes[0].data.diagnostics).toEqual([]);
  });

  it('keeps the ports of an unknown node type that edges name, so its wires still show', () => {
    expect(nodes[2].data.def).toBeUndefined();
    expect(nodes[2].data.orphanPorts).toEqual({ inputs: ['in'], outputs: [] });
  });

  it('colours each wire by the type of its source port', () => {
    const edges = toFlowEdges(doc, registry, new Set(['e2']));
    expect(edges[0]).toMatchObject({
      source: 'p',
      sourceHandle: 'out:point',
      target: 'l',
      targetHandle: 'in:a',
    });
    expect(edges[0].style?.stroke).toBe(PORT_TYPE_INFO.point.color);
    expect(edges[1].style?.stroke).toBe(PORT_TYPE_INFO.line.color);
    expect(edges[1].selected).toBe(true);
  });
});
