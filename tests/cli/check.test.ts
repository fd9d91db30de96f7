/**
 * `kleinflow check` also compiles the scene's shader, so the problems only the GPU program has
 * (KF404 uniform budget, KF405 values beyond float32 range) are listed like every other one.
 */
import { writeFileSync } from 'node:fs';
import { join } from 'node:path';
import { describe, expect, it } from 'vitest';
import { LIMITS } from '../../nodes/core/scene.ts';
import { groupNodes } from '../../nodes/graph/grouping.ts';
import { doc, edge, node } from '../nodes/support/doc.ts';
import { cliTempDir, graphText, runCli, writeIn } from './run-cli.ts';

const dir = cliTempDir('kleinflow-check-');

type Node = { id: string; type: string; position: [number, number]; params: Record<string, unknown> };
/** A graph file: inversions in the given circles, all wired into one render node. */
function inversions(name: string, circles: { c: [number, number]; r: number }[], extra: Node[] = []) {
  const nodes: Node[] = circles.map((circle, i) => ({
    id: `inv${i}`,
    type: 'inversion',
    position: [0, i * 100],
    params: { circle },
  }));
  nodes.push({ id: 'out', type: 'render', position: [400, 0], params: {} }, ...extra);
  const edges = circles.map((_, i) => ({
    id: `e${i}`,
    from: { node: `inv${i}`, port: 'element' },
    to: { node: 'out', port: 'elements' },
  }));
  return writeIn(dir, name, graphText(nodes, edges));
}

describe('kleinflow check: shader diagnostics', () => {
  it('lists KF405 for a circle beyond the GPU range once, as a warning (exit 0)', () => {
    const path = inversions('huge.json', [
      { c: [0, 0], r: 1 },
      { c: [0, 0], r: 1e30 },
    ]);
    const r = runCli(['check', path]);
    expect(r.status).toBe(0);
    const lines = r.stdout.trim().split('\n');
    expect(lines).toEqual([
      expect.stringMatching(
        /^warning KF405 nodes\[1\] \(node "inv1"\): a value of 1e\+30 is beyond what the GPU computes with/,
      ),
    ]);
    expect(r.stderr).toMatch(/huge\.json: 0 errors, 1 warning/);
  });

  it('lists KF404 when the elements need more uniform vectors than every GPU has', () => {
    const n = LIMITS.maxUniformVectors + 10;
    const circles = Array.from({ length: n }, (_, i) => ({ c: [i * 3, 0] as [number, number], r: 1 }));
    const r = runCli(['check', inversions('many.json', circles)]);
    expect(r.status).toBe(0);
    expect(r.stdout).toMatch(
      new RegExp(
        `^warning KF404 .*\\(node "out"\\): the scene needs \\d+ uniform vectors, more than the ${LIMITS.maxUniformVectors}`,
        'm',
      ),
    );
  });

  it('still exits 1 when the evaluation has an error, and prints the shader warning too', () => {
    const broken: Node = { id: 'x', type: 'foo', position: [0, 0], params: {} };
    const path = inversions('both.json', [{ c: [0, 0], r: 1e30 }], [broken]);
    const r = runCli(['check', path]);
    expect(r.status).toBe(1);
    expect(r.stdout).toMatch(/^error KF203 nodes\[2\]\.type \(node "x"\)/m);
    expect(r.stdout).toMatch(/^warning KF405 nodes\[0\] \(node "inv0"\)/m);
    expect(r.stderr).toMatch(/both\.json: 1 error, 1 warning/);
  });
});

describe('kleinflow check: nodes inside groups', () => {
  it('names a grouped node by its id in the document and the group it is in, with its JSON path', () => {
    const flat = doc(
      [node('c', 'circle', { radius: -1 }), node('i', 'inversion'), node('out', 'render')],
      [edge('e1', 'c.circle', 'i.circle'), edge('e2', 'i.element', 'out.elements')],
    );
    const path = join(dir, 'grouped.json');
    writeFileSync(path, JSON.stringify(groupNodes(flat, ['c', 'i'], 'g')));
    const r = runCli(['check', path]);
    expect(r.status).not.toBe(0);
    expect(r.stdout).toMatch(
      /error KF\d+ nodes\[\d+\]\.group\.nodes\[\d+\]\.params\.radius \(node "c" in group "g"\)/,
    );
  });
});

describe('kleinflow check: document text with control characters', () => {
  it('escapes them in every line it prints: no terminal escape, no faked line', () => {
    const evil = '\u001b]0;owned\u0007\u001b[2J\r\nb.json: ok\u009b\u202e';
    const odd: Node = { id: evil, type: `t${evil}`, position: [0, 0], params: {} };
    const path = inversions('evil.json', [{ c: [0, 0], r: 1 }], [odd]);
    const r = runCli(['check', path]);
    expect(r.status).toBe(1);
    // Nothing but printable text and the line breaks between messages.
    // biome-ignore lint/suspicious/noControlCharactersInRegex: the characters that must not come out
    expect(r.stdout + r.stderr).not.toMatch(/[\u0000-\u0009\u000b-\u001f\u007f-\u009f\u202a-\u202e]/);
    const lines = r.stdout.trim().split('\n');
    expect(lines).toHaveLength(1);
    expect(lines[0]).toMatch(
      /^error KF203 nodes\[2\]\.type \(node "\\x1b\]0;owned\\x07\\x1b\[2J\\r\\nb\.json: ok/,
    );
    expect(r.stderr.trim().split('\n')).toEqual([expect.stringMatching(/evil\.json: 1 error, 0 warnings$/)]);
  });
});

describe('kleinflow check: a 3D graph beyond the GPU range', () => {
  it('warns (KF405) for a seed sphere centred at 1e308, which the shader would write as 3.4e38', () => {
    const graph = doc(
      [
        node('m', 'sphere-inversion', { sphere: { center: [0, 0, 0], radius: 1 } }),
        node('s', 'seed-sphere', { center: [1e308, 0, 0], radius: 0.5, color: '#ffffff' }),
        node('out', 'render-3d', { camera: [4, 0, 0], target: [0, 0, 0] }),
      ],
      [edge('e1', 'm.element', 'out.elements'), edge('e2', 's.seed', 'out.seeds')],
    );
    const path = join(dir, 'far-3d.json');
    writeFileSync(path, JSON.stringify(graph));
    const r = runCli(['check', path]);
    expect(r.stdout).toMatch(
      /^warning KF405 .*\(node "out", port "seeds"\): a value of 1e\+308 is beyond .*so seed "s" does not draw/m,
    );
  });
});
