import { defineNode } from '../core/define-node.ts';
import type { LoxodromicElement } from '../core/scene-elements.ts';
import { circleThrough3, GEOMETRY_EPS, invertPoint } from '../geometry/circle.ts';
import { twoCircleRegions } from '../geometry/mobius.ts';
import { dist, normalize, perp, sub } from '../geometry/vec.ts';
import { fail } from './shared.ts';

export const loxodromicNode = defineNode({
  type: 'loxodromic',
  version: 1,
  label: 'Loxodromic',
  category: 'Generators',
  color: '#e85d75',
  doc: 'A loxodromic generator from two nested circles (C2 around C1) and a control point P that sets the twist.',
  inputs: {
    c1: { type: 'circle', label: 'C1', default: { c: [0, 0], r: 1 } },
    c2: { type: 'circle', label: 'C2', default: { c: [0.3, 0], r: 2 } },
    control: { type: 'point', label: 'P', default: [0.2, 0.6] },
  },
  outputs: { element: { type: 'element', label: 'element' }, orthogonal: { type: 'circle', label: 'C3' } },
  params: {},
  evaluate: ({ inputs, nodeId }) => {
    const { c1, c2, control: P } = inputs;
    const d = dist(c1.c, c2.c);
    const tol = GEOMETRY_EPS * Math.max(1, c2.r);
    if (d <= tol) return fail('C1 and C2 are concentric: the line through their centres is undefined');
    if (!(d < c1.r && d + c1.r <= c2.r)) {
      return fail("needs nested circles: C2's centre inside C1, and C1 inside C2");
    }
    if (Math.abs(dist(P, c1.c) - c1.r) <= tol || Math.abs(dist(P, c2.c) - c2.r) <= tol) {
      return fail('the control point P lies on C1 or C2: move it off the circles');
    }
    const dir = normalize(sub(c2.c, c1.c));
    const ln = perp(dir);
    const off = (P[0] - c1.c[0]) * ln[0] + (P[1] - c1.c[1]) * ln[1];
    if (Math.abs(off) <= tol)
      return fail('P lies on the line through the centres: the map is only hyperbolic there');
    const p1 = invertPoint(c1, P);
    const p2 = invertPoint(c2, P);
    const c3 = p1 && p2 ? circleThrough3(P, p1, p2) : null;
    if (!c3) return fail('the control point gives no circle orthogonal to C1 and C2: move P');
    const regions = twoCircleRegions(c1, c2);
    if (!regions.ok) return fail(regions.reason);
    const element: LoxodromicElement = {
      kind: 'loxodromic',
      nodeId,
      c1,
      c2,
      c3,
      lq: c1.c,
      ln,
      a: regions.a,
      b: regions.b,
    };
    return { outputs: { element: [element], orthogonal: c3 }, readout: 'loxodromic' };
  },
  overlay: (ctx, out) => [
    { shape: 'circle', circle: out.orthogonal },
    { shape: 'point', at: ctx.inputs.control },
  ],
  handles: (ctx) => [{ handle: 'control', at: ctx.inputs.control }],
  drag: (_h, to) => ({ control: [...to] }),
});
