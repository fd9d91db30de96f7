/**
 * Muted nodes (docs/architecture.md "Muted nodes"): element outputs empty, same-typed inputs passed
 * through, everything else absent with a quiet "input muted" (KF313) downstream, never an error cascade.
 */
import { describe, expect, it } from 'vitest';
import { evaluateGraph } from '../../../nodes/graph/evaluate.ts';
import { registry } from '../../../nodes/types/index.ts';
import { doc, edge, node } from '../support/doc.ts';

const muted = <T extends { muted?: boolean }>(n: T): T => ({ ...n, muted: true });

/** p1, p2 → midpoint → circle (centre) → inversion → render. */
const chain = (mute: string | null) =>
  doc(
    [
      node('p1', 'point', { x: 0, y: 0 }),
      node('p2', 'point', { x: 2, y: 0 }),
      node('m', 'midpoint'),
      node('c', 'circle', { radius: 0.5 }),
      node('i', 'inversion'),
      node('out', 'render'),
    ].map((n) => (n.id === mute ? muted(n) : n)),
    [
      edge('e1', 'p1.point', 'm.a'),
      edge('e2', 'p2.point', 'm.b'),
      edge('e3', 'm.point', 'c.center'),
      edge('e4', 'c.circle', 'i.circle'),
      edge('e5', 'i.element', 'out.elements'),
    ],
  );

describe('muted nodes', () => {
  it('a muted element node contributes no elements and no overlay, without any error', () => {
    const ev = evaluateGraph(chain('i'), registry);
    expect(ev.scene.elements).toEqual([]);
    expect(ev.diagnostics.filter((d) => d.severity === 'error')).toEqual([]);
    expect(ev.nodes.get('i')?.muted).toBe(true);
    expect(ev.scene.overlays.some((o) => o.nodeId === 'i')).toBe(false);
    expect(evaluateGraph(chain(null), registry).scene.elements).toHaveLength(1);
  });

  it('a node with a same-typed input passes its first one through (midpoint → its input a)', () => {
    const ev = evaluateGraph(chain('m'), registry);
    expect(ev.nodes.get('m')?.outputs).toEqual({ point: [0, 0] });
    expect(ev.scene.elements[0]).toMatchObject({ kind: 'inversion', c: [0, 0], r: 0.5 });
  });

  it('a muted node with nothing to pass on: dependants report KF313 "input muted" (info), no error cascade', () => {
    const ev = evaluateGraph(chain('c'), registry); // a circle has no circle input
    const i = ev.nodes.get('i')!;
    expect(i.muted).toBe(true);
    expect(i.outputs).toBeUndefined();
    expect(i.diagnostics).toEqual([
      expect.objectContaining({ code: 'KF313', severity: 'info', port: 'circle', nodeId: 'i' }),
    ]);
    expect(i.diagnostics[0].message).toContain('“Circle” is muted');
    // The render takes many elements: the quiet inversion simply adds none; nothing is an error.
    expect(ev.diagnostics.filter((d) => d.severity !== 'info')).toEqual([]);
    expect(ev.scene.elements).toEqual([]);
    expect(ev.scene.renderNodeId).toBe('out');
  });

  it('a muted render node draws nothing; unmuting (no key) is the old result', () => {
    expect(evaluateGraph(chain('out'), registry).scene.renderNodeId).toBeNull();
    const d = chain(null);
    expect(evaluateGraph(d, registry).scene).toEqual(
      evaluateGraph({ ...d, nodes: d.nodes.map((n) => ({ ...n, muted: false })) }, registry).scene,
    );
  });

  it('an optional input fed by a muted node is simply unconnected (the kaleidoscope disk as clip)', () => {
    const k = (mute: boolean) =>
      doc(
        [node('k', 'kaleidoscope'), node('k2', 'k-mirror'), node('out', 'render')].map((n) =>
          mute && n.id === 'k' ? muted(n) : n,
        ),
        [
          edge('e1', 'k.elements', 'out.elements'),
          edge('e2', 'k.boundary', 'out.clip'),
          edge('e3', 'k2.elements', 'out.elements'),
        ],
      );
    const ev = evaluateGraph(k(true), registry);
    expect(ev.scene.clip).toBeNull();
    expect(ev.scene.elements.every((e) => e.nodeId === 'k2')).toBe(true);
    expect(ev.nodes.get('out')?.diagnostics.map((d) => d.code)).toEqual(['KF313']);
    expect(evaluateGraph(k(false), registry).scene.clip).not.toBeNull();
  });

  it('a muted sphere inversion leaves the 3D scene exactly as without it, with no message downstream', async () => {
    const { readFileSync } = await import('node:fs');
    const file = new URL(
      '../../../examples/3d/fig11-sphere-inversion-fractal.kleinflow.json',
      import.meta.url,
    );
    const fig11 = JSON.parse(readFileSync(file, 'utf8')) as ReturnType<typeof doc>;
    const withMuted = { ...fig11, nodes: fig11.nodes.map((n) => (n.id === 'inv3' ? muted(n) : n)) };
    const ev = evaluateGraph(withMuted, registry);
    expect(ev.scene3d?.elements).toHaveLength(5);
    expect(ev.scene3d?.elements.some((e) => (e as { nodeId?: string }).nodeId === 'inv3')).toBe(false);
    expect(ev.diagnostics.filter((d) => d.severity !== 'info')).toEqual([]);
    expect(ev.nodes.get('render')?.diagnostics.map((d) => d.code)).not.toContain('KF313');
    expect(evaluateGraph(fig11, registry).scene3d?.elements).toHaveLength(6);
  });
});
