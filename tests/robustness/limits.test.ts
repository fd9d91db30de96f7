/**
 * Every limit Kleinflow enforces says so in words, at the place that broke it, without doing the
 * heavy work first: node count (KF105), scene elements (KF401) and the uniform budget (KF404),
 * iterations and samples (KF301 with the path), text lengths, the number of listed schema
 * problems, share links and image sizes.
 */
import { describe, expect, it } from 'vitest';
import { LIMITS, type Scene } from '../../nodes/core/scene.ts';
import type { GraphEdge, GraphNode } from '../../nodes/graph/document.ts';
import { evaluateGraph } from '../../nodes/graph/evaluate.ts';
import { loadDocument, parseDocumentText } from '../../nodes/graph/load.ts';
import { registry } from '../../nodes/types/index.ts';
import { compile } from '../../shader-gen/compile.ts';
import { uniformRows } from '../../shader-gen/glsl/values.ts';
import { parseSizeOption } from '../../src/cli/args.ts';
import { decodeShareFragment, encodeShareFragment } from '../../src/io/share-url.ts';
import { scaleGraph } from '../bench/scale.ts';
import { checkPipeline } from '../fuzz/pipeline-check.ts';
import { doc, edge, node } from '../nodes/support/doc.ts';

/** `count` circles, each inverted and wired into one render node. */
function inversionsDoc(count: number) {
  const nodes: GraphNode[] = [node('out', 'render')];
  const edges: GraphEdge[] = [];
  for (let i = 0; i < count; i++) {
    nodes.push(node(`c${i}`, 'circle', { center: [i * 0.01, 0], radius: 0.001 }), node(`i${i}`, 'inversion'));
    edges.push(edge(`a${i}`, `c${i}.circle`, `i${i}.circle`), edge(`b${i}`, `i${i}.element`, 'out.elements'));
  }
  return doc(nodes, edges);
}

describe('document size', () => {
  it(`refuses more than ${LIMITS.maxNodes} nodes with KF105 before validating any of them`, () => {
    // Every node is garbage: had the loader validated them, it would list schema problems.
    const value = { ...doc([]), nodes: Array.from({ length: LIMITS.maxNodes + 1 }, () => ({ bogus: true })) };
    const t0 = performance.now();
    const r = loadDocument(value, registry);
    const ms = performance.now() - t0;
    expect(r.ok).toBe(false);
    expect(r.diagnostics).toEqual([
      expect.objectContaining({
        code: 'KF105',
        path: 'nodes',
        message: `document has ${LIMITS.maxNodes + 1} nodes; the limit is ${LIMITS.maxNodes}`,
      }),
    ]);
    expect(ms).toBeLessThan(200); // generous on a busy machine; it is one length check
  });

  it(`loads exactly ${LIMITS.maxNodes} nodes`, () => {
    const nodes = Array.from({ length: LIMITS.maxNodes }, (_, i) => node(`n${i}`, 'number', { value: i }));
    const r = parseDocumentText(JSON.stringify(doc(nodes)), registry);
    expect(r.ok).toBe(true);
  });

  it(`evaluates and compiles a graph of exactly ${LIMITS.maxNodes} nodes, warning only about the element cap`, () => {
    const report = checkPipeline({ text: JSON.stringify(scaleGraph(LIMITS.maxNodes)) });
    expect(report.problems).toEqual([]);
    expect(report.stage).toBe('compile');
    expect(report.scene!.elements).toHaveLength(LIMITS.maxElements);
    const notable = report.diagnostics.filter((d) => d.severity !== 'info').map((d) => d.code);
    expect([...new Set(notable)].sort()).toEqual(['KF401', 'KF404']);
  }, 60_000);

  it('lists at most 50 schema problems and counts the rest', () => {
    const nodes = Array.from({ length: 200 }, (_, i) => ({ id: `n${i}`, type: 'point', params: {} }));
    const r = loadDocument({ ...doc([]), nodes }, registry);
    expect(r.ok).toBe(false);
    expect(r.diagnostics).toHaveLength(51);
    expect(r.diagnostics[50].message).toBe('…and 150 more problems');
    expect(r.diagnostics[0]).toMatchObject({ code: 'KF102', path: 'nodes[0].position' });
  });

  it.each([
    [
      'a node id',
      (d: ReturnType<typeof doc>) => ({ ...d, nodes: [node('x'.repeat(201), 'point')] }),
      'nodes[0].id',
    ],
    [
      'a label',
      (d: ReturnType<typeof doc>) => ({ ...d, nodes: [{ ...node('p', 'point'), label: 'x'.repeat(201) }] }),
      'nodes[0].label',
    ],
    ['the title', (d: ReturnType<typeof doc>) => ({ ...d, meta: { title: 'x'.repeat(501) } }), 'meta.title'],
    [
      'the description',
      (d: ReturnType<typeof doc>) => ({ ...d, meta: { description: 'x'.repeat(20_001) } }),
      'meta.description',
    ],
  ])('refuses an over-long %s with its path', (_what, mutate, path) => {
    const r = loadDocument(mutate(doc([])), registry);
    expect(r.ok).toBe(false);
    expect(r.diagnostics[0]).toMatchObject({ code: 'KF102', path });
    expect(r.diagnostics[0].message.length).toBeLessThan(200);
  });
});

describe('render settings', () => {
  it.each([
    ['maxIterations', LIMITS.maxIterations + 1, `expected a number ≤ ${LIMITS.maxIterations}`],
    ['maxIterations', 0, 'expected a number ≥ 1'],
    ['maxIterations', 10.5, 'expected an integer'],
    ['samples', LIMITS.maxSamples + 1, `expected a number ≤ ${LIMITS.maxSamples}`],
  ])('refuses %s = %s with a message naming the path', (name, value, text) => {
    const ev = evaluateGraph(doc([node('p', 'point'), node('out', 'render', { [name]: value })]), registry);
    const d = ev.diagnostics.find((x) => x.code === 'KF301');
    expect(d).toMatchObject({ severity: 'error', nodeId: 'out', path: `nodes[1].params.${name}` });
    expect(d!.message).toContain(text);
    expect(ev.scene.renderNodeId).toBeNull(); // nothing half-configured is drawn
  });

  it(`accepts maxIterations = ${LIMITS.maxIterations}`, () => {
    const ev = evaluateGraph(doc([node('out', 'render', { maxIterations: LIMITS.maxIterations })]), registry);
    expect(ev.scene.maxIterations).toBe(LIMITS.maxIterations);
  });
});

describe('scene size', () => {
  const n = LIMITS.maxElements + 44;

  it(`keeps the first ${LIMITS.maxElements} of ${n} elements, says so on the render node, and compiles within the uniform budget`, () => {
    const report = checkPipeline({ value: inversionsDoc(n) });
    expect(report.problems).toEqual([]);
    const kf401 = report.diagnostics.filter((d) => d.code === 'KF401');
    expect(kf401[0]).toMatchObject({ nodeId: 'out' });
    expect(kf401[0].message).toBe(
      `the scene has ${n} elements; the limit is ${LIMITS.maxElements} (the extra ones are ignored)`,
    );
    const scene = report.scene!;
    expect(scene.elements).toHaveLength(LIMITS.maxElements);
    expect(scene.elements[0].nodeId).toBe('i0');

    const program = compile(scene);
    const rows = program.uniforms.reduce((sum, u) => sum + uniformRows(u), 0);
    expect(rows).toBeLessThanOrEqual(LIMITS.maxUniformVectors);
    if (program.diagnostics.some((d) => d.code === 'KF404')) expect(program.uniforms).toEqual([]);
  });

  it('compile itself truncates an over-long scene it is handed, naming the first dropped element', () => {
    const ev = evaluateGraph(inversionsDoc(3), registry);
    const one = ev.scene.elements[0];
    const big: Scene = {
      ...ev.scene,
      elements: Array.from({ length: n }, (_, i) => ({ ...one, nodeId: `x${i}` })),
    };
    const program = compile(big);
    const d = program.diagnostics.find((x) => x.code === 'KF401');
    expect(d).toMatchObject({ nodeId: `x${LIMITS.maxElements}` });
    const emitted = new Set(Object.values(program.lineMap));
    expect(emitted.has(`x${LIMITS.maxElements - 1}`)).toBe(true);
    expect(emitted.has(`x${LIMITS.maxElements}`)).toBe(false);
  });

  it('moves values into the shader (KF404) when they would not fit the uniforms, naming the render node', () => {
    const ev = evaluateGraph(inversionsDoc(LIMITS.maxUniformVectors), registry);
    const program = compile(ev.scene);
    const d = program.diagnostics.find((x) => x.code === 'KF404');
    expect(d).toMatchObject({ severity: 'warning', nodeId: 'out' });
    expect(d!.message).toMatch(/uniform vectors, more than the 208/);
    const rows = program.uniforms.reduce((sum, u) => sum + uniformRows(u), 0);
    expect(rows).toBeLessThanOrEqual(LIMITS.maxUniformVectors);
  });
});

describe('numbers the GPU cannot compute with', () => {
  it.each([
    [1e20, 0.5],
    [0, 3.5e38],
    [-1e308, 1],
  ])('circle at (%s, 0) with radius %s: compiles, warns KF405 on the element’s node', (x, r) => {
    const d = doc(
      [node('c', 'circle', { center: [x, 0], radius: r }), node('i', 'inversion'), node('out', 'render')],
      [edge('e1', 'c.circle', 'i.circle'), edge('e2', 'i.element', 'out.elements')],
    );
    const report = checkPipeline({ value: d });
    expect(report.problems).toEqual([]);
    const program = compile(report.scene!);
    const warning = program.diagnostics.find((x) => x.code === 'KF405');
    expect(warning).toMatchObject({ severity: 'warning', nodeId: 'i' });
    expect(warning!.message).toContain('beyond what the GPU computes with (±1e+19)');
  });

  it(`stays quiet up to ${LIMITS.gpuMaxMagnitude}`, () => {
    const d = doc(
      [
        node('c', 'circle', { center: [LIMITS.gpuMaxMagnitude, 0], radius: 1 }),
        node('i', 'inversion'),
        node('out', 'render'),
      ],
      [edge('e1', 'c.circle', 'i.circle'), edge('e2', 'i.element', 'out.elements')],
    );
    const program = compile(evaluateGraph(d, registry).scene);
    expect(program.diagnostics.filter((x) => x.code === 'KF405')).toEqual([]);
  });
});

describe('share links and images', () => {
  it('refuses to make a share link longer than the cap, with a message', () => {
    // Incompressible ids: random-looking text deflates poorly.
    let x = 12345;
    const noise = () => {
      let s = '';
      for (let i = 0; i < 190; i++) {
        x = (Math.imul(x, 1103515245) + 12345) >>> 0;
        s += String.fromCharCode(33 + ((x >>> 16) % 90));
      }
      return s;
    };
    const nodes = Array.from({ length: 2_500 }, () => ({ ...node(noise(), 'point'), label: noise() }));
    const r = encodeShareFragment(doc(nodes));
    expect(r.ok).toBe(false);
    expect(!r.ok && r.message).toMatch(/too large for a share link .* save it as a file instead/);
  });

  it('refuses a share fragment over the cap before decoding it', () => {
    const r = decodeShareFragment(`#g=${'A'.repeat(LIMITS.shareFragmentMaxChars + 1)}`);
    expect(r).toEqual({
      ok: false,
      message: `the share link is too long (${LIMITS.shareFragmentMaxChars + 1} characters; the limit is ${LIMITS.shareFragmentMaxChars})`,
    });
  });

  it(`refuses image sizes over ${LIMITS.maxImageSide} pixels a side with the bounds in the message`, () => {
    expect(() => parseSizeOption('size', `${LIMITS.maxImageSide + 1}x10`, LIMITS.maxImageSide)).toThrow(
      `--size must be between 1 and ${LIMITS.maxImageSide}, got ${LIMITS.maxImageSide + 1}`,
    );
    expect(parseSizeOption('size', `${LIMITS.maxImageSide}x1`, LIMITS.maxImageSide)).toEqual({
      width: LIMITS.maxImageSide,
      height: 1,
    });
  });
});
