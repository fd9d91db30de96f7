import { mkdirSync, readFileSync, writeFileSync } from 'node:fs';
import { join } from 'node:path';
import { describe, expect, it } from 'vitest';
import { interpret } from '../../shader-gen/interpret.ts';
import { decodePng, encodePng, readPngText } from '../../src/io/png.ts';
import { cliTempDir, evaluateFile, graphText, ROOT, runCli, runCliOk, writeIn } from './run-cli.ts';
import { runMain } from './run-main.ts';

const EXAMPLE = join(ROOT, 'examples/hyperbolic-237.kleinflow.json');
const dir = cliTempDir('kleinflow-cli-');
const file = (name: string, content: string) => writeIn(dir, name, content);
const graph = graphText;
/** No line of a stack trace ("    at fn (file:line)") and no raw Error dump. */
const expectNoTrace = (text: string) => {
  expect(text).not.toMatch(/^\s+at .+/m);
  expect(text).not.toMatch(/Error:.*\n.*node:internal/);
};

describe('kleinflow render', () => {
  it('writes a PNG of the requested size with the graph embedded', () => {
    const out = join(dir, 'out.png');
    const r = runCliOk(['render', EXAMPLE, '-o', out, '--size', '48x32', '--samples', '2']);
    expect(r.stdout).toContain('48×32');
    const bytes = new Uint8Array(readFileSync(out));
    const png = decodePng(bytes);
    expect([png.width, png.height]).toEqual([48, 32]);
    expect(readPngText(bytes)?.kleinflow).toBe(readFileSync(EXAMPLE, 'utf8'));
    // the Poincaré disk is drawn: the centre differs from the corner (background)
    const at = (x: number, y: number) =>
      Array.from(png.data.subarray((y * 48 + x) * 4, (y * 48 + x) * 4 + 3));
    expect(at(24, 16)).not.toEqual(at(0, 0));
  });

  it('renders a PNG that Kleinflow exported (its embedded graph) again', () => {
    const first = join(dir, 'first.png');
    const second = join(dir, 'second.png');
    expect(runCli(['render', EXAMPLE, '-o', first, '--size', '16x16']).status).toBe(0);
    const r = runCli(['render', first, '-o', second, '--size', '16x16']);
    expect(r.status).toBe(0);
    expect(readFileSync(second)).toEqual(readFileSync(first));
  });

  it.each([
    [['render', EXAMPLE], /missing -o/],
    [['render', '-o', 'x.png'], /missing GRAPH/],
    [['render', EXAMPLE, '-o', 'x.png', '--size', '10by10'], /--size expects WIDTHxHEIGHT/],
    [['render', EXAMPLE, '-o', 'x.png', '--size', '0x10'], /--size must be between 1 and/],
    [['render', EXAMPLE, '-o', 'x.png', '--samples', '2.5'], /--samples expects a whole number/],
    [['render', EXAMPLE, '-o', 'x.png', '--frobnicate'], /unknown option --frobnicate/],
    [['render', EXAMPLE, '-o'], /option -o needs a value/],
  ])('usage error %j exits 2 with the usage text', async (args, message) => {
    const r = await runMain(args);
    expect(r.status).toBe(2);
    expect(r.stderr).toMatch(message);
    expect(r.stderr).toContain('Usage: kleinflow render');
    expectNoTrace(r.stderr);
  });

  it('refuses a graph with errors and writes nothing', async () => {
    const bad = file(
      'cycle.json',
      graph(
        [
          { id: 'a', type: 'number', position: [0, 0], params: {} },
          { id: 'b', type: 'number', position: [0, 0], params: {} },
        ],
        [
          { id: 'e1', from: { node: 'a', port: 'value' }, to: { node: 'b', port: 'value' } },
          { id: 'e2', from: { node: 'b', port: 'value' }, to: { node: 'a', port: 'value' } },
        ],
      ),
    );
    const out = join(dir, 'never.png');
    const r = await runMain(['render', bad, '-o', out]);
    expect(r.status).toBe(1);
    expect(r.stderr).toMatch(/error KF208 nodes\[0\] \(node "a"\): cycle through nodes/);
    expect(r.stderr).toMatch(/has 2 errors; nothing was produced/);
    expect(() => readFileSync(out)).toThrow();
  });

  it('says so when the output cannot be written', () => {
    const r = runCli(['render', EXAMPLE, '-o', join(dir, 'no/such/folder/x.png'), '--size', '4x4']);
    expect(r.status).toBe(1);
    expect(r.stderr).toMatch(/cannot write ".*x\.png": no such file/);
    expectNoTrace(r.stderr);
  });
});

describe('kleinflow sample', () => {
  it('prints depth, final point and escaped flag in input order, equal to interpret()', () => {
    const pts: [number, number][] = [
      [0.1, 0.2],
      [-0.5, 0.3],
      [0.9, -0.1],
      [0.999, 0],
      [3, 3],
    ];
    const ptsFile = file('pts.json', JSON.stringify(pts));
    const r = runCliOk(['sample', EXAMPLE, '--points', ptsFile]);
    const out = JSON.parse(r.stdout) as { points: Record<string, unknown>[] };
    expect(Object.keys(out)).toEqual(['points']);
    const { scene } = evaluateFile(EXAMPLE);
    expect(out.points).toHaveLength(pts.length);
    out.points.forEach((p, i) => {
      expect(Object.keys(p)).toEqual(['depth', 'x', 'y', 'escaped']);
      const want = interpret(scene, pts[i]);
      expect(p).toEqual({ depth: want.depth, x: want.final[0], y: want.final[1], escaped: want.escaped });
    });
    expect(out.points.some((p) => (p.depth as number) > 0)).toBe(true);
  });

  it.each([
    ['not JSON', '[[0,0],', /"[^"]*bad-points\.json" is not valid JSON/],
    ['not an array', '{"x":1}', /expected an array of \[x, y\] points, got an object/],
    ['a bad entry', '[[0,0],[1,"a"]]', /bad-points\.json"\[1\]: expected \[x, y\] with two finite numbers/],
    ['a triple', '[[0,0,0]]', /"\[0\]: expected \[x, y\]/],
  ])('rejects a points file that is %s with one clear line', async (_what, content, message) => {
    const r = await runMain(['sample', EXAMPLE, '--points', file('bad-points.json', content)]);
    expect(r.status).toBe(1);
    expect(r.stdout).toBe('');
    expect(r.stderr.trim().split('\n')).toHaveLength(1);
    expect(r.stderr).toMatch(message);
  });

  it('--trace prints every step (element, node label, point, factor) and why it stopped', () => {
    const pts: [number, number][] = [
      [0.9, -0.1],
      [0.1, 0.2],
      [0.2, 0.04],
    ];
    const r = runCliOk([
      'sample',
      EXAMPLE,
      '--points',
      file('trace-pts.json', JSON.stringify(pts)),
      '--trace',
    ]);
    const { scene } = evaluateFile(EXAMPLE);
    const out = JSON.parse(r.stdout) as {
      points: {
        depth: number;
        x: number;
        y: number;
        escaped: boolean;
        stop: string;
        steps: Record<string, unknown>[];
      }[];
    };
    out.points.forEach((p, i) => {
      const want = interpret(scene, pts[i]);
      // The traced result is the untraced one, plus the steps.
      expect([p.depth, p.x, p.y, p.escaped]).toEqual([want.depth, ...want.final, want.escaped]);
      expect(p.stop).toBe('fundamental-domain');
      expect(p.steps).toHaveLength(want.depth); // reflections only: one step per depth
      p.steps.forEach((s, k) => {
        expect(Object.keys(s)).toEqual(['element', 'node', 'label', 'depth', 'x', 'y', 'factor']);
        expect(s.node).toBe('k');
        expect(s.label).toBe(`Triangle kaleidoscope ${(s.element as number) + 1}`);
        expect(s.depth).toBe(k + 1);
      });
      const last = p.steps.at(-1);
      if (last) expect([last.x, last.y, last.factor]).toEqual([...want.final, want.scale]);
    });
    expect(out.points[0].steps.length).toBeGreaterThan(3);
    expect(out.points[2].steps).toEqual([]);
    expect(out.points[2].depth).toBe(0);
    // Without --trace nothing changes.
    const plain = runCli(['sample', EXAMPLE, '--points', join(dir, 'trace-pts.json')]);
    expect(plain.stdout).not.toContain('steps');
  });

  it('needs --points', async () => {
    const r = await runMain(['sample', EXAMPLE]);
    expect(r.status).toBe(2);
    expect(r.stderr).toMatch(/missing --points/);
  });
});

describe('kleinflow check', () => {
  it('exits 0 and prints nothing on stdout for a clean example', async () => {
    const r = await runMain(['check', EXAMPLE]);
    expect(r.status).toBe(0);
    expect(r.stdout).toBe('');
    expect(r.stderr).toMatch(/: ok/);
  });

  it('lists every problem with its path and node id, and exits 1', async () => {
    const bad = file(
      'broken.json',
      graph(
        [
          { id: 'k', type: 'kaleidoscope', position: [0, 0], params: { p: 1 } },
          { id: 'x', type: 'foo', position: [0, 0], params: {} },
          { id: 'out', type: 'render', position: [0, 0], params: {} },
        ],
        [{ id: 'e1', from: { node: 'k', port: 'elements' }, to: { node: 'gone', port: 'elements' } }],
      ),
    );
    const r = await runMain(['check', bad]);
    expect(r.status).toBe(1);
    const lines = r.stdout.trim().split('\n');
    expect(lines).toContain(
      'error KF203 nodes[1].type (node "x"): unknown node type "foo" (kept as a placeholder; its data is preserved)',
    );
    expect(lines).toContain(
      'error KF204 edges[0].to.node: edge target names node "gone", which does not exist',
    );
    expect(
      lines.some((l) => /^error KF301 nodes\[0\]\.params\.p \(node "k"\): p: expected a number ≥ 2/.test(l)),
    ).toBe(true);
    expect(r.stderr).toMatch(/broken\.json: 3 errors/);
  });

  it('allows warnings (exit 0)', async () => {
    const warn = file(
      'warn.json',
      graph([{ id: 'p', type: 'point', position: [0, 0], params: { colour: 1 } }]),
    );
    const r = await runMain(['check', warn]);
    expect(r.status).toBe(0);
    expect(r.stdout).toMatch(
      /^warning KF301 nodes\[0\]\.params\.colour \(node "p"\): .*has no parameter "colour"/m,
    );
    expect(r.stdout).toMatch(/^warning KF210 \(document\): the graph has no render node/m);
  });

  it.each([
    ['not JSON', '{"format": "kleinflow", ', /^error KF101 \(document\): not valid JSON/],
    ['another format', '{"format": "flower"}', /^error KF103 format: not a Kleinflow document/],
    [
      'a schema violation',
      graph([{ id: 'a', type: 'point', position: [0], params: {} }]),
      /^error KF102 nodes\[0\]\.position/,
    ],
    ['from the future', JSON.stringify({ format: 'kleinflow', version: 99 }), /^error KF\d+ .*version/],
  ])('reports a file that is %s and exits 1', async (_what, content, message) => {
    const r = await runMain(['check', file('doc.json', content)]);
    expect(r.status).toBe(1);
    expect(r.stdout).toMatch(message);
    expectNoTrace(r.stdout + r.stderr);
  });

  it.each([
    ['a missing file', () => join(dir, 'nope.json'), /cannot read ".*nope\.json": no such file/],
    ['a directory', () => dir, /cannot read ".*": it is a directory/],
    ['a binary file', () => file('bin.json', '\u0000\u00ff\u00fe'), /is not a text file|not valid JSON/],
    [
      'a PNG without a graph',
      () => {
        const p = join(dir, 'plain.png');
        writeFileSync(p, encodePng({ width: 1, height: 1, data: new Uint8Array(4) }));
        return p;
      },
      /is a PNG without an embedded Kleinflow graph/,
    ],
  ])('reports %s in one line and exits 1', async (_what, path, message) => {
    const r = await runMain(['check', path()]);
    expect(r.status).toBe(1);
    expect(r.stdout + r.stderr).toMatch(message);
    expectNoTrace(r.stdout + r.stderr);
  });

  it('checks several files, prefixing each line with its file, and fails if any fails', async () => {
    mkdirSync(join(dir, 'many'), { recursive: true });
    const bad = file('many/bad.json', graph([{ id: 'x', type: 'foo', position: [0, 0], params: {} }]));
    const r = await runMain(['check', EXAMPLE, bad]);
    expect(r.status).toBe(1);
    expect(r.stdout).toContain(`${bad}: error KF203 nodes[0].type (node "x")`);
  });
});

describe('kleinflow usage', () => {
  it('help lists every command and exits 0', () => {
    const r = runCli(['help']);
    expect(r.status).toBe(0);
    for (const name of ['render', 'sample', 'check', 'help'])
      expect(r.stdout).toMatch(new RegExp(`^  ${name} `, 'm'));
  });

  it.each([['--help'], ['-h']])('%s prints the usage', async (flag) => {
    const r = await runMain([flag]);
    expect(r.status).toBe(0);
    expect(r.stdout).toContain('Usage: kleinflow COMMAND');
  });

  it('COMMAND --help and help COMMAND print that command’s usage', async () => {
    expect((await runMain(['sample', '--help'])).stdout).toContain('Usage: kleinflow sample');
    expect((await runMain(['help', 'check'])).stdout).toContain('Usage: kleinflow check');
  });

  it('an unknown command or no command is a usage error (exit 2)', () => {
    const unknown = runCli(['paint', 'x.json']);
    expect(unknown.status).toBe(2);
    expect(unknown.stderr).toMatch(/unknown command "paint"/);
    expect(unknown.stderr).toContain('Usage: kleinflow COMMAND');
    const none = runCli([]);
    expect(none.status).toBe(2);
    expect(none.stderr).toContain('Usage: kleinflow COMMAND');
  });
});
