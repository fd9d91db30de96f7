/** The render pane's message for graphs without a picture: calm unless there is a real error. */
import { describe, expect, it } from 'vitest';
import { evaluateGraph } from '../../../nodes/graph/evaluate.ts';
import { registry } from '../../../nodes/types/index.ts';
import { HINTS, renderHint } from '../../../src/app/render-hint.ts';
import { doc, edge, node } from '../../nodes/support/doc.ts';

const hintOf = (d: ReturnType<typeof doc>) => renderHint(d, evaluateGraph(d, registry), registry);

describe('renderHint', () => {
  it('is calm and says what is missing for empty and unfinished graphs', () => {
    expect(hintOf(doc([]))).toEqual({ tone: 'calm', text: HINTS.empty });
    expect(hintOf(doc([node('p', 'point')]))).toEqual({ tone: 'calm', text: HINTS.noRender });
    expect(hintOf(doc([node('r', 'render')]))).toEqual({ tone: 'calm', text: HINTS.noElements });
  });

  it('names the node and its error when something upstream of Render fails', () => {
    const d = doc(
      [node('c', 'circle', { radius: -1 }), node('i', 'inversion'), node('r', 'render')],
      [edge('e1', 'c.circle', 'i.circle'), edge('e2', 'i.element', 'r.elements')],
    );
    const hint = hintOf(d);
    expect(hint?.tone).toBe('error');
    expect(hint?.nodeId).toBeDefined();
    expect(hint?.text).toMatch(/^No picture: /);
    const ev = evaluateGraph(d, registry);
    const first = ev.diagnostics.find((x) => x.severity === 'error' && x.nodeId === hint?.nodeId);
    expect(hint?.text).toContain(first?.message);
  });

  it('names the Render node’s own field error although elements are wired (not "wire a mirror")', () => {
    const d = doc(
      [node('c', 'circle', { radius: 1 }), node('i', 'inversion'), node('r', 'render', { samples: -3 })],
      [edge('e1', 'c.circle', 'i.circle'), edge('e2', 'i.element', 'r.elements')],
    );
    const hint = hintOf(d);
    expect(hint).toMatchObject({ tone: 'error', nodeId: 'r' });
    expect(hint?.text).toMatch(/^No picture: Render — .*samples/);
  });

  it('says nothing when the picture is there', () => {
    const d = doc(
      [node('c', 'circle', { radius: 1 }), node('i', 'inversion'), node('r', 'render')],
      [edge('e1', 'c.circle', 'i.circle'), edge('e2', 'i.element', 'r.elements')],
    );
    expect(hintOf(d)).toBeNull();
  });

  it('a 3D render shows its picture; a failing one names its error, not "add a Render node"', () => {
    const ok = doc(
      [
        node('s', 'sphere'),
        node('i', 'sphere-inversion'),
        node('g', 'seed-sphere', { center: [3, 0, 0] }),
        node('r', 'render-3d'),
      ],
      [
        edge('e1', 's.sphere', 'i.sphere'),
        edge('e2', 'i.element', 'r.elements'),
        edge('e3', 'g.seed', 'r.seeds'),
      ],
    );
    expect(hintOf(ok)).toBeNull();
    // The camera on the point it looks at: the render node itself fails, and the hint says so.
    const bad = doc([node('r', 'render-3d', { camera: [1, 1, 1], target: [1, 1, 1] })]);
    expect(hintOf(bad)).toMatchObject({ tone: 'error', nodeId: 'r' });
    expect(hintOf(bad)?.text).toMatch(/^No picture: Render 3D — .*coincide/);
  });
});
