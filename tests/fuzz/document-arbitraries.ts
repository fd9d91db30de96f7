/**
 * fast-check arbitraries for hostile Kleinflow documents: arbitrary JSON, documents with the right
 * skeleton but arbitrary contents (real node types and port names, random wiring), and mutations
 * of the shipped examples (fields deleted, duplicated or retyped; dangling, self and cycle edges;
 * wrong ports and types; extreme numbers and number-like strings). Every choice comes from
 * fast-check, so a fixed seed gives the same documents every run.
 */
import { readFileSync } from 'node:fs';
import fc from 'fast-check';
import { canConnect } from '../../nodes/core/ports.ts';
import { registry } from '../../nodes/types/index.ts';
import { exampleNames, examplePath } from '../../src/cli/examples.ts';

type Json = null | boolean | number | string | Json[] | { [key: string]: Json };
type JsonObject = { [key: string]: Json };

/** Numbers at the edges of float64 and of what the geometry accepts. */
export const EXTREME_NUMBERS = [
  0,
  -0,
  1,
  -1,
  2,
  0.5,
  1e308,
  -1e308,
  5e-324,
  -5e-324,
  1e-300,
  1e300,
  1.7976931348623157e308,
  Number.MAX_SAFE_INTEGER,
  1e6,
  1e-9,
  3.4028235e38,
  1e39,
] as const;

/** Strings that a careless reader might turn into numbers or special values. */
const TRICKY_STRINGS = ['NaN', 'Infinity', '-Infinity', '1e999', '', ' ', '0x10', '__proto__', 'constructor'];

const TYPES = registry.all.map((d) => d.type);
const INPUT_NAMES = [...new Set(registry.all.flatMap((d) => Object.keys(d.inputs)))];
const OUTPUT_NAMES = [...new Set(registry.all.flatMap((d) => Object.keys(d.outputs)))];
const PARAM_NAMES = [
  ...new Set(registry.all.flatMap((d) => [...Object.keys(d.inputs), ...Object.keys(d.params)])),
];

/** A value for a hostile field: extreme numbers, tricky strings, or any small JSON. */
export const hostileValue: fc.Arbitrary<Json> = fc.oneof(
  fc.constantFrom<Json>(...EXTREME_NUMBERS),
  fc.constantFrom<Json>(...TRICKY_STRINGS),
  fc.constantFrom<Json>(null, true, false, [], {}, [0], [0, 0], [1e308, -1e308], [5e-324, 0], [0, 0, 0]),
  fc.record({ c: fc.tuple(fc.double(), fc.double()), r: fc.double() }).map((v) => json(v)),
  fc.jsonValue({ maxDepth: 3 }) as fc.Arbitrary<Json>,
);

/** JSON.stringify turns NaN/∞ into null, as a file written by any other tool would. */
function json(v: unknown): Json {
  return JSON.parse(JSON.stringify(v)) as Json;
}

const nodeId = fc.oneof(
  fc.constantFrom('a', 'b', 'c', 'd', 'e', 'out', 't'),
  fc.string({ minLength: 1, maxLength: 4 }),
);

/** Right skeleton, arbitrary contents: real types, real port names, random wiring and params. */
export const skeletonDocument: fc.Arbitrary<Json> = fc
  .record({
    nodes: fc.array(
      fc.record({
        id: nodeId,
        // Render nodes get a weight of their own: a graph reaches compile only through one, and
        // their share among TYPES shrinks with every node type added.
        type: fc.oneof(
          { weight: 5, arbitrary: fc.constantFrom(...TYPES) },
          { weight: 1, arbitrary: fc.constantFrom('render', 'render-3d') },
          fc.string({ maxLength: 6 }),
        ),
        position: fc.oneof({ weight: 9, arbitrary: fc.constant<Json>([0, 0]) }, hostileValue),
        params: fc.dictionary(fc.constantFrom(...PARAM_NAMES), hostileValue, { maxKeys: 4 }),
      }),
      { maxLength: 8 },
    ),
    edges: fc.array(
      fc.record({
        id: fc.string({ minLength: 1, maxLength: 3 }),
        from: fc.record({ node: nodeId, port: fc.constantFrom(...OUTPUT_NAMES) }),
        to: fc.record({ node: nodeId, port: fc.constantFrom(...INPUT_NAMES) }),
      }),
      { maxLength: 10 },
    ),
    view: fc.oneof({ weight: 9, arbitrary: fc.constant<Json>({ center: [0, 0], scale: 4 }) }, hostileValue),
    version: fc.oneof({ weight: 9, arbitrary: fc.constant<Json>(1) }, hostileValue),
    // The presentation's step notes (meta.stepNotes, keyed by node id): text, or anything else.
    stepNotes: fc.option(
      fc.dictionary(nodeId, fc.oneof({ weight: 4, arbitrary: fc.string() }, hostileValue), { maxKeys: 4 }),
      {
        nil: undefined,
      },
    ),
  })
  .map(({ nodes, edges, view, version, stepNotes }) =>
    json({
      format: 'kleinflow',
      version,
      meta: stepNotes === undefined ? { title: 'fuzz' } : { title: 'fuzz', stepNotes },
      nodes,
      edges,
      view,
    }),
  );

export interface Example {
  readonly name: string;
  readonly doc: JsonObject;
}

/** Every examples/*.kleinflow.json, read when the test runs. */
export function readExamples(): Example[] {
  return exampleNames().map((name) => ({
    name: `${name}.kleinflow.json`,
    doc: JSON.parse(readFileSync(examplePath(name), 'utf8')) as JsonObject,
  }));
}

/** Every [container, key] inside `root` (objects and arrays, depth-first, document order). */
function slots(root: Json): [Json[] | JsonObject, string | number][] {
  const out: [Json[] | JsonObject, string | number][] = [];
  const walk = (v: Json) => {
    if (Array.isArray(v)) {
      for (let i = 0; i < v.length; i++) {
        out.push([v, i]);
        walk(v[i]);
      }
    } else if (v !== null && typeof v === 'object') {
      for (const [k, x] of Object.entries(v)) {
        out.push([v, k]);
        walk(x);
      }
    }
  };
  walk(root);
  return out;
}

type Node = { id: string; type: string; params: JsonObject };
type Edge = { id: string; from: { node: string; port: string }; to: { node: string; port: string } };

/** A mutation: `pick`/`pick2` choose places (taken modulo what exists), `value` a hostile value. */
export interface Mutation {
  readonly op: (typeof OPS)[number];
  readonly pick: number;
  readonly pick2: number;
  readonly value: Json;
  readonly word: string;
}

const OPS = [
  'delete',
  'duplicate',
  'retype',
  'extremeNumber',
  'danglingEdge',
  'selfEdge',
  'cycleEdge',
  'reverseEdge',
  'wrongPort',
  'wrongType',
  'badParam',
  'dropNode',
] as const;

export const mutation: fc.Arbitrary<Mutation> = fc.record({
  op: fc.constantFrom(...OPS),
  pick: fc.nat(),
  pick2: fc.nat(),
  value: hostileValue,
  word: fc.oneof(fc.constantFrom(...INPUT_NAMES, ...OUTPUT_NAMES, ...TYPES), fc.string({ maxLength: 5 })),
});

const nodesOf = (doc: JsonObject): Node[] =>
  Array.isArray(doc.nodes) ? (doc.nodes.filter((n) => n && typeof n === 'object') as unknown as Node[]) : [];
const edgesOf = (doc: JsonObject): Json[] => (Array.isArray(doc.edges) ? doc.edges : []);
const at = <T>(xs: readonly T[], i: number): T | undefined => (xs.length ? xs[i % xs.length] : undefined);

/** A wire from an output of `from` into an input of `to` whose port types connect, if any. */
function compatibleEdge(from: Node, to: Node, id: string): Edge | undefined {
  const src = registry.get(from.type);
  const dst = registry.get(to.type);
  if (!src || !dst) return undefined;
  for (const [out, o] of Object.entries(src.outputs))
    for (const [inp, i] of Object.entries(dst.inputs))
      if (canConnect(o.type, i.type))
        return { id, from: { node: from.id, port: out }, to: { node: to.id, port: inp } };
  return undefined;
}

/** Applies one mutation in place (the document is a private deep copy). */
export function applyMutation(doc: JsonObject, m: Mutation): void {
  const nodes = nodesOf(doc);
  const edges = edgesOf(doc);
  const newEdge = (e: Edge) => edges.push(e as unknown as Json);
  switch (m.op) {
    case 'delete': {
      const s = at(slots(doc), m.pick);
      if (!s) return;
      const [c, k] = s;
      if (Array.isArray(c)) c.splice(k as number, 1);
      else delete c[k as string];
      return;
    }
    case 'duplicate': {
      const s = at(slots(doc), m.pick);
      if (!s) return;
      const [c, k] = s;
      const copy = structuredClone((c as Record<string | number, Json>)[k]);
      // An array item is doubled in place (duplicate ids, edges); an object gets a twin key.
      if (Array.isArray(c)) c.splice(k as number, 0, copy);
      else c[m.word || 'extra'] = copy;
      return;
    }
    case 'retype': {
      const s = at(slots(doc), m.pick);
      if (s) (s[0] as Record<string | number, Json>)[s[1]] = m.value;
      return;
    }
    case 'extremeNumber': {
      const numeric = slots(doc).filter(
        ([c, k]) => typeof (c as Record<string | number, Json>)[k] === 'number',
      );
      const s = at(numeric, m.pick);
      if (s)
        (s[0] as Record<string | number, Json>)[s[1]] = EXTREME_NUMBERS[m.pick2 % EXTREME_NUMBERS.length];
      return;
    }
    case 'danglingEdge': {
      const to = at(nodes, m.pick);
      newEdge({
        id: `fz${m.pick}`,
        from: { node: `ghost${m.word}`, port: 'point' },
        to: { node: to?.id ?? 'x', port: m.word },
      });
      return;
    }
    case 'selfEdge': {
      const n = at(nodes, m.pick);
      if (n)
        newEdge(
          compatibleEdge(n, n, `fz${m.pick}`) ?? {
            id: `fz${m.pick}`,
            from: { node: n.id, port: m.word },
            to: { node: n.id, port: m.word },
          },
        );
      return;
    }
    case 'cycleEdge': {
      // An edge back up from the target of an existing edge to its source closes a cycle.
      const e = at(edges, m.pick) as unknown as Edge | undefined;
      const from = nodes.find((n) => n.id === e?.to?.node);
      const to = nodes.find((n) => n.id === e?.from?.node);
      if (from && to) {
        const back = compatibleEdge(from, to, `fz${m.pick}`);
        if (back) newEdge(back);
      }
      return;
    }
    case 'reverseEdge': {
      const e = at(edges, m.pick) as unknown as Edge | undefined;
      if (e?.from && e.to) [e.from, e.to] = [e.to, e.from];
      return;
    }
    case 'wrongPort': {
      const e = at(edges, m.pick) as unknown as Edge | undefined;
      if (e?.from && e.to) (m.pick2 % 2 ? e.from : e.to).port = m.word;
      return;
    }
    case 'wrongType': {
      const n = at(nodes, m.pick);
      if (n) n.type = m.pick2 % 3 === 0 ? m.word : TYPES[m.pick2 % TYPES.length];
      return;
    }
    case 'badParam': {
      const n = at(nodes, m.pick);
      const def = n && registry.get(n.type);
      if (!n || !def || !n.params || typeof n.params !== 'object') return;
      const names = [...Object.keys(def.inputs), ...Object.keys(def.params)];
      const name = at(names, m.pick2);
      if (name) n.params[name] = m.value;
      return;
    }
    case 'dropNode': {
      if (Array.isArray(doc.nodes) && doc.nodes.length) doc.nodes.splice(m.pick % doc.nodes.length, 1);
      return;
    }
  }
}

/** An example with 1–4 mutations applied, as JSON text. */
export function mutatedExample(examples: readonly Example[]): fc.Arbitrary<{ name: string; text: string }> {
  return fc
    .tuple(fc.nat({ max: examples.length - 1 }), fc.array(mutation, { minLength: 1, maxLength: 4 }))
    .map(([i, ms]) => {
      const doc = structuredClone(examples[i].doc);
      for (const m of ms) applyMutation(doc, m);
      return { name: examples[i].name, text: JSON.stringify(doc) };
    });
}
