import { describe, expect, it } from 'vitest';
import { createRegistry } from '../../../../nodes/core/registry.ts';
import type { InversionElement, ReflectionElement } from '../../../../nodes/core/scene.ts';
import { evaluateGraph } from '../../../../nodes/graph/evaluate.ts';
import { NODE_TYPES, registry } from '../../../../nodes/types/index.ts';
import { interpret } from '../../../../shader-gen/interpret.ts';
import { importFlower } from '../../../../src/io/flower/import.ts';
import { circleMirror, fedge, fnode, fpoint, graph, lineMirror } from './support/flower-fixture.ts';
import { imported, messages } from './support/imported.ts';

describe('Flower import: node types', () => {
  it('Point: position from posX/posY; its first Float input drives y, the second x', () => {
    const json = graph({
      nodes: [
        fnode('Constant', 'k', { value: 3 }),
        fnode('Constant', 'j', { value: -2 }),
        fpoint('p', 1.5, -2.5),
      ],
      edges: [fedge('Float', 'k', 'p', 0), fedge('Float', 'j', 'p', 1, true)],
    });
    const { doc, errors, scene } = imported(json);
    expect(errors).toEqual([]);
    const point = doc.nodes.find((n) => n.type === 'point')!;
    expect(point.params).toEqual({ x: 1.5, y: -2.5 });
    const numbers = doc.nodes.filter((n) => n.type === 'number');
    expect(numbers.map((n) => n.params.value)).toEqual([3, -2]);
    const intoPoint = doc.edges.filter((e) => e.to.node === point.id).map((e) => [e.from.node, e.to.port]);
    expect(intoPoint).toEqual([
      [numbers[0].id, 'y'],
      [numbers[1].id, 'x'],
    ]);
    expect(scene.handles.find((h) => h.nodeId === point.id)?.at).toEqual([-2, 3]);
  });

  it('Point without a saved position is placed at the origin with a note', () => {
    const { doc, notes } = imported(graph({ nodes: [fnode('Point', 'p')], edges: [] }));
    expect(doc.nodes[0].params).toEqual({ x: 0, y: 0 });
    expect(messages(notes)).toEqual([expect.stringMatching(/no saved position/)]);
  });

  for (const reverse of [false, true]) {
    it(`LineTwoPoints + LineMirror (reverse ${reverse}): same line, kept side ${reverse ? 'right' : 'left'} of p1 → p2`, () => {
      const { doc, scene, errors, notes } = imported(graph(lineMirror('m', [1, 1], [3, 2], reverse)));
      expect(errors).toEqual([]);
      expect(notes).toEqual([]);
      const line = doc.nodes.find((n) => n.type === 'line')!;
      const [a, b] = ['a', 'b'].map(
        (port) => doc.edges.find((e) => e.to.node === line.id && e.to.port === port)!.from.node,
      );
      expect(doc.nodes.find((n) => n.id === a)!.params).toEqual({ x: 1, y: 1 });
      expect(doc.nodes.find((n) => n.id === b)!.params).toEqual({ x: 3, y: 2 });
      expect(doc.nodes.find((n) => n.type === 'reflection')!.params).toEqual({ flip: reverse });
      const [el] = scene.elements as ReflectionElement[];
      expect(el.q).toEqual([1, 1]);
      // Left of (1,1) → (3,2) is up-left, e.g. (1, 3); right is (3, 0).
      const left = interpret(scene, [1, 3]);
      const right = interpret(scene, [3, 0]);
      expect([left.depth, right.depth]).toEqual(reverse ? [1, 0] : [0, 1]);
    });
  }

  it('CircleThreePoints + CircleMirror: inversion in the circle through the three points', () => {
    const { scene, errors } = imported(
      graph(
        circleMirror('c', [
          [2, 0],
          [0, 2],
          [-2, 0],
        ]),
      ),
    );
    expect(errors).toEqual([]);
    const [el] = scene.elements as InversionElement[];
    expect(el.kind).toBe('inversion');
    expect(el.c[0]).toBeCloseTo(0, 12);
    expect(el.c[1]).toBeCloseTo(0, 12);
    expect(el.r).toBeCloseTo(2, 12);
  });

  it('mirrors are wired into the render in Flower order: every circle first, then the lines', () => {
    const json = graph(
      lineMirror('l1', [0, -5], [0, 5], false),
      circleMirror('c1', [
        [10, 1],
        [11, 0],
        [10, -1],
      ]),
      lineMirror('l2', [5, 5], [-5, 5], true),
      circleMirror('c2', [
        [-10, 1],
        [-11, 0],
        [-10, -1],
      ]),
    );
    const { doc, scene } = imported(json);
    expect(scene.elements.map((e) => `${e.kind}:${e.nodeId}`)).toEqual([
      'inversion:mirror-01',
      'inversion:mirror-02',
      'reflection:mirror-03',
      'reflection:mirror-04',
    ]);
    const inv = scene.elements as InversionElement[];
    expect(inv[0].c[0]).toBeCloseTo(10, 9);
    expect(inv[1].c[0]).toBeCloseTo(-10, 9);
    const render = doc.nodes.find((n) => n.type === 'render')!;
    expect(render.params).toEqual({ maxIterations: 50, samples: 20 });
  });

  it('mirrors pass their input through: a line taken from a LineMirror output is the same line', () => {
    const base = lineMirror('m', [0, 0], [1, 0], false);
    const json = graph(base, {
      nodes: [fnode('LineMirror', 'm2', { reverse: true })],
      edges: [fedge('Line', 'm', 'm2', 0)],
    });
    const { scene } = imported(json);
    const [a, b] = scene.elements as ReflectionElement[];
    expect(b.q).toEqual(a.q);
    expect(b.n[1]).toBeCloseTo(-a.n[1], 12);
  });

  const sinWaveGraph = () =>
    graph({
      nodes: [
        fnode('SinWave', 's', { period: 2000, amplitude: 10, phaseShift: 0.5, offset: 1, value: -8.5 }),
        fpoint('p', 1, -8.5),
      ],
      edges: [fedge('Float', 's', 'p', 0)],
    });

  it('SinWave becomes a sine node driven by a Time node (Flower periods are milliseconds)', () => {
    const { doc, notes, errors } = imported(sinWaveGraph());
    expect(errors).toEqual([]);
    expect(notes).toEqual([]);
    const sine = doc.nodes.find((n) => n.type === 'sine')!;
    expect(sine.params).toEqual({ amplitude: 10, period: 2, phase: 0.5, offset: 1 });
    const time = doc.nodes.find((n) => n.type === 'time')!;
    expect(doc.edges).toContainEqual(
      expect.objectContaining({ from: { node: time.id, port: 'time' }, to: { node: sine.id, port: 't' } }),
    );
    // At t = 0.5 s the point's y is 1 + 10·sin(2π·0.5/2 + 0.5).
    const point = doc.nodes.find((n) => n.type === 'point')!;
    const at = evaluateGraph(doc, registry, { time: 0.5 }).scene.handles.find(
      (h) => h.nodeId === point.id,
    )!.at;
    expect(at[1]).toBeCloseTo(1 + 10 * Math.sin(Math.PI / 2 + 0.5), 12);
  });

  it('SinWave without a Kleinflow sine node: its saved value as a Number, with a note', () => {
    const withoutSine = createRegistry(NODE_TYPES.filter((t) => t.type !== 'sine'));
    const r = importFlower(sinWaveGraph(), withoutSine);
    if (!r.ok) throw new Error('import failed');
    expect(r.doc.nodes.find((n) => n.type === 'number')?.params).toEqual({ value: -8.5 });
    expect(messages(r.notes)).toEqual([
      expect.stringMatching(/SinWave "s" cannot be mapped yet.*-8\.5.*animation is lost/),
    ]);
  });

  it('CircularMotion becomes circular-motion driven by Time; OrbitSeed becomes a seed picture', () => {
    const json = graph({
      nodes: [
        fnode('CircularMotion', 'cm', { centerX: 1, centerY: 2, radius: 3, period: 4000, phaseShift: 0 }),
        fnode('LineTwoPoints', 'L'),
        fpoint('q', 5, 5),
        fnode('OrbitSeed', 'os', { posX: 0, posY: 0, width: 1, height: 1 }),
      ],
      edges: [fedge('Point', 'cm', 'L', 0), fedge('Point', 'q', 'L', 1)],
    });
    const { doc, notes, errors } = imported(json);
    expect(errors).toEqual([]);
    const motion = doc.nodes.find((n) => n.type === 'circular-motion')!;
    expect(motion.params).toEqual({ center: [1, 2], radius: 3, period: 4, phase: 0 });
    expect(doc.edges.some((e) => e.from.node === motion.id && e.to.port === 'a')).toBe(true);
    expect(doc.nodes.find((n) => n.type === 'seed-image')?.params).toEqual({
      center: [0.5, 0.5],
      width: 1,
      height: 1,
      rotation: 0,
    });
    expect(messages(notes)).toEqual([
      expect.stringMatching(/OrbitSeed "os": Flower's seed picture is not carried over/),
      expect.stringMatching(/OrbitSeed "os": .*fields are guessed/),
    ]);
    const bare = imported(graph({ nodes: [fnode('CircularMotion', 'cm')], edges: [] }));
    expect(messages(bare.notes)).toEqual([expect.stringMatching(/no saved centre, radius, period found/)]);
  });

  it('unwired construction inputs use Kleinflow defaults, hidden, with a note', () => {
    const { doc, notes, errors } = imported(graph({ nodes: [fnode('CircleThreePoints', 'c')], edges: [] }));
    expect(errors).toEqual([]);
    expect(doc.nodes.find((n) => n.type === 'circle-3pt')!.params).toEqual({ visible: false });
    expect(messages(notes)).toEqual([expect.stringMatching(/no point wired into "a", "b", "c"/)]);
  });
});
