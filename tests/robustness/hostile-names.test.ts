/**
 * Regression tests for what the fuzzer found: names that exist on every JavaScript object
 * ("constructor", "toString", "__proto__") used as ports, ids, types and params; values too deep
 * or too long to echo back in a message; and the whole-document warning that named no place.
 */
import { describe, expect, it } from 'vitest';
import { LIMITS } from '../../nodes/core/scene.ts';
import { describeValue } from '../../nodes/graph/describe-value.ts';
import { evaluateGraph } from '../../nodes/graph/evaluate.ts';
import { parseDocumentText } from '../../nodes/graph/load.ts';
import { registry } from '../../nodes/types/index.ts';
import { checkPipeline } from '../fuzz/pipeline-check.ts';
import { doc, edge, node } from '../nodes/support/doc.ts';

const OBJECT_NAMES = ['constructor', 'toString', '__proto__', 'hasOwnProperty', 'valueOf'];

describe('names that every JavaScript object has', () => {
  for (const name of OBJECT_NAMES) {
    it(`an edge into or out of port "${name}" is an unknown port (KF205), not a crash`, () => {
      const d = doc(
        [node('c', 'circle'), node('i', 'inversion'), node('out', 'render')],
        [edge('e1', `c.${name}`, 'i.circle'), edge('e2', 'i.element', `out.${name}`)],
      );
      const report = checkPipeline({ value: d });
      expect(report.problems).toEqual([]);
      const unknown = report.diagnostics.filter((x) => x.code === 'KF205');
      expect(unknown.map((x) => x.path)).toEqual(['edges[0].from.port', 'edges[1].to.port']);
    });

    it(`"${name}" as a node id, a node type and a param is handled like any other name`, () => {
      // Written as text: JSON.parse makes "__proto__" an ordinary own key, as a file would.
      const text = JSON.stringify(
        doc([node(name, 'point', { x: 1 }), node('t', name), node('out', 'render')]),
      ).replace('"params":{"x":1}', `"params":{"x":1,"${name}":2}`);
      const report = checkPipeline({ text });
      expect(report.problems).toEqual([]);
      expect(report.diagnostics).toContainEqual(
        expect.objectContaining({ code: 'KF203', nodeId: 't', path: 'nodes[1].type' }),
      );
      // zod's record copy drops a "__proto__" key (assigning it only sets a prototype): nothing to warn about.
      if (name !== '__proto__')
        expect(report.diagnostics).toContainEqual(
          expect.objectContaining({ code: 'KF301', severity: 'warning', path: `nodes[0].params.${name}` }),
        );
    });
  }

  it('a "__proto__" object in params or meta pollutes nothing and is not read as params', () => {
    const text = JSON.stringify(doc([node('c', 'circle'), node('out', 'render')]))
      .replace('"params":{}', '"params":{"__proto__":{"radius":-5,"polluted":1}}')
      .replace('"meta":{', '"meta":{"__proto__":{"polluted":1},');
    const report = checkPipeline({ text });
    expect(report.problems).toEqual([]);
    expect(({} as Record<string, unknown>).polluted).toBeUndefined();
    expect(report.diagnostics.filter((d) => d.severity === 'error')).toEqual([]);
  });
});

describe('describeValue (what "got …" shows in a message)', () => {
  it('writes small values as JSON', () => {
    expect(describeValue([1, 2])).toBe('[1,2]');
    expect(describeValue({ c: [0, 0], r: -1 })).toBe('{"c":[0,0],"r":-1}');
    expect(describeValue('abc')).toBe('"abc"');
    expect(describeValue(null)).toBe('null');
    expect(describeValue(Number.NaN)).toBe('NaN');
    expect(describeValue(undefined)).toBe('undefined');
  });

  it('keeps a 10 MB string, a 10,000-level nesting and a million items short', () => {
    let deep: unknown = 0;
    for (let i = 0; i < 10_000; i++) deep = [deep];
    for (const v of ['x'.repeat(10_000_000), deep, Array.from({ length: 1_000_000 }, (_, i) => i)]) {
      const s = describeValue(v);
      expect(s.length).toBeLessThanOrEqual(60);
      expect(s.endsWith('...') || s.includes('…')).toBe(true);
    }
    expect(describeValue(deep)).toBe('[[[[…]]]]');
  });
});

describe('messages that echo a value stay short and never throw', () => {
  it('a 10 MB "format" is refused with a short KF103', () => {
    const r = parseDocumentText(JSON.stringify({ ...doc([]), format: 'k'.repeat(10_000_000) }), registry);
    expect(r.ok).toBe(false);
    expect(r.diagnostics[0]).toMatchObject({ code: 'KF103', path: 'format' });
    expect(r.diagnostics[0].message.length).toBeLessThan(200);
  });

  it('a 10,000-level nested "format" or "version" is refused with a message (JSON.stringify overflowed here)', () => {
    const nested = `${'['.repeat(10_000)}${']'.repeat(10_000)}`;
    const base = JSON.stringify(doc([]));
    for (const field of ['format', 'version']) {
      const text = base.replace(
        field === 'format' ? '"kleinflow"' : '"version":1',
        field === 'format' ? nested : `"version":${nested}`,
      );
      const r = parseDocumentText(text, registry);
      expect(r.ok).toBe(false);
      expect(r.diagnostics[0].message.length).toBeLessThan(500); // the path to the 64th level is most of it;
    }
  });

  it(`refuses nesting deeper than ${LIMITS.maxJsonDepth} levels with the path, so what loads can always be saved`, () => {
    const nest = (depth: number) => `${'['.repeat(depth)}0${']'.repeat(depth)}`;
    const at = (value: string) =>
      JSON.stringify(doc([node('c', 'circle')])).replace('"params":{}', `"params":{"zz":${value}}`);
    // The document is level 0, nodes 1, the node 2, params 3, "zz" 4.
    const fits = parseDocumentText(at(nest(LIMITS.maxJsonDepth - 4)), registry);
    expect(fits.ok).toBe(true);
    if (fits.ok) expect(() => structuredClone(fits.doc)).not.toThrow();
    const deep = parseDocumentText(at(nest(10_000)), registry);
    expect(deep.ok).toBe(false);
    const d = deep.diagnostics[0];
    expect(d).toMatchObject({ code: 'KF102' });
    expect(d.path).toMatch(/^nodes\[0\]\.params\.zz(\[0\])+$/);
    expect(d.message).toContain(`nested deeper than ${LIMITS.maxJsonDepth} levels`);
    expect(parseDocumentText(at(nest(LIMITS.maxJsonDepth - 3)), registry).ok).toBe(false);
  });

  it('a graph without a render node says so at the document (KF210 has a path)', () => {
    const ev = evaluateGraph(doc([node('p', 'point')]), registry);
    expect(ev.diagnostics).toContainEqual(expect.objectContaining({ code: 'KF210', path: '(document)' }));
  });
});
