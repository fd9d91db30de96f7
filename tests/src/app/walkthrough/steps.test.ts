/** The walkthrough's checks read the live document: each step ticks off when it is done. */
import { describe, expect, it } from 'vitest';
import { evaluateGraph } from '../../../../nodes/graph/evaluate.ts';
import { registry } from '../../../../nodes/types/index.ts';
import { walkthroughStatus } from '../../../../src/app/walkthrough/steps.ts';
import { doc, edge, node } from '../../../nodes/support/doc.ts';

const corners = [
  [-1, -0.5774],
  [1, -0.5774],
  [0, 1.1547],
];

/** The *333 graph up to `upTo` steps; `reversed` draws the last line C→A the wrong way (A→C). */
function build(upTo: number, reversed = false, flipLast = false) {
  const nodes = corners.map(([x, y], i) => node(`p${i}`, 'point', { x, y }));
  const edges = [];
  if (upTo >= 2)
    for (let i = 0; i < 3; i++) {
      nodes.push(node(`l${i}`, 'line'));
      const [a, b] = reversed && i === 2 ? [0, 2] : [i, (i + 1) % 3];
      edges.push(edge(`a${i}`, `p${a}.point`, `l${i}.a`), edge(`b${i}`, `p${b}.point`, `l${i}.b`));
    }
  if (upTo >= 3)
    for (let i = 0; i < 3; i++) {
      nodes.push(node(`m${i}`, 'reflection', i === 2 && flipLast ? { flip: true } : {}));
      edges.push(edge(`lm${i}`, `l${i}.line`, `m${i}.line`));
    }
  if (upTo >= 4) {
    nodes.push(node('r', 'render'));
    for (let i = 0; i < 3; i++) edges.push(edge(`mr${i}`, `m${i}.element`, 'r.elements'));
  }
  const d = doc(nodes, edges);
  return walkthroughStatus(d, evaluateGraph(d, registry));
}

const doneCount = (s: ReturnType<typeof build>) => s.filter((x) => x.done).length;

describe('walkthroughStatus', () => {
  it('ticks off one step per stage of the construction', () => {
    expect(doneCount(walkthroughStatus(doc([]), evaluateGraph(doc([]), registry)))).toBe(0);
    expect(doneCount(build(1))).toBe(1);
    expect(doneCount(build(2))).toBe(2);
    expect(doneCount(build(3))).toBe(3);
    expect(doneCount(build(4))).toBe(5);
  });

  it('names a mirror that keeps the outside, and is satisfied once it is flipped', () => {
    const wrong = build(4, true);
    expect(wrong[4].done).toBe(false);
    expect(wrong[4].todo).toMatch(/^Line reflection 3 keeps the outside/);
    expect(wrong[4].flip).toEqual(['m2']);
    expect(build(4, true, true)[4].done).toBe(true);
  });

  it('says how far a step has got', () => {
    expect(build(1)[1].todo).toBe('0 lines with both ends wired to points');
  });
});
