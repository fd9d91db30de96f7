/**
 * The sphere through four points, or the paper's Sphere(P, P′, P″, Q) (§5.1.2): through a control
 * point P, its inverses P′ in S1 and P″ in S2, and Q — a sphere orthogonal to S1 and S2
 * (docs/math-3d.md §1), the kind the compound loxodromic generator twists with.
 */
import { defineNode } from '../core/define-node.ts';
import type { Vec3 } from '../core/scene-3d.ts';
import { invertInSphere, sphereFromFourPoints, sphereThroughInverses } from '../geometry/space/sphere.ts';
import { fail, fmt, VISIBLE } from './shared.ts';
import { fmt3, point3Input, sphereInput, sphereProblem } from './space-shared.ts';

const CORNERS = ['a', 'b', 'c', 'd'] as const;
const CONTROLS = ['p', 'q'] as const;
const FOUR = { param: 'mode', is: ['four-points'] } as const;
const INVERSES = { param: 'mode', is: ['inverses'] } as const;

export const sphere4ptNode = defineNode({
  type: 'sphere-4pt',
  version: 1,
  label: 'Sphere through 4 points',
  category: '3D',
  color: '#3fa7d6',
  doc: 'The sphere through four points (not in one plane), or through P, its inverses in S1 and S2, and Q (a sphere at right angles to S1 and S2).',
  inputs: {
    a: { ...point3Input('a', 1, 0, 0), when: FOUR },
    b: { ...point3Input('b', 0, 1, 0), when: FOUR },
    c: { ...point3Input('c', 0, 0, 1), when: FOUR },
    d: { ...point3Input('d', -1, 0, 0), when: FOUR },
    s1: { ...sphereInput('S1', [-1.5, 0, 0], 1), when: INVERSES },
    s2: { ...sphereInput('S2', [1.5, 0, 0], 1), when: INVERSES },
    p: {
      ...point3Input('P', 0, 0.5, 0.5, 'the sphere passes through P, P′ = I_S1(P) and P″ = I_S2(P)'),
      when: INVERSES,
    },
    q: { ...point3Input('Q', 0, 1, -0.5, 'and through Q'), when: INVERSES },
  },
  outputs: { sphere: { type: 'sphere', label: 'sphere' } },
  params: {
    mode: {
      kind: 'enum',
      default: 'four-points',
      options: ['four-points', 'inverses'],
      label: 'through',
      doc: 'four-points: a, b, c, d; inverses: Sphere(P, P′, P″, Q) of the paper’s §5.1.2',
    },
    visible: VISIBLE,
  },
  evaluate: ({ inputs: i, params }) => {
    if (params.mode === 'inverses') {
      const problem = sphereProblem(i.s1, 'S1') ?? sphereProblem(i.s2, 'S2');
      if (problem) return fail(problem);
    }
    const s =
      params.mode === 'inverses'
        ? sphereThroughInverses(i.s1, i.s2, i.p, i.q)
        : sphereFromFourPoints(i.a, i.b, i.c, i.d);
    if (!s.ok) return fail(s.error);
    return { outputs: { sphere: s.value }, readout: `${fmt3(s.value.center)}, r = ${fmt(s.value.radius)}` };
  },
  overlay3d: ({ inputs: i, params }, out) => {
    const through: Vec3[] =
      params.mode === 'inverses'
        ? [i.p, invertInSphere(i.s1, i.p)?.x, invertInSphere(i.s2, i.p)?.x, i.q].filter(
            (x) => x !== undefined,
          )
        : CORNERS.map((k) => i[k]);
    return [
      { shape: 'sphere', sphere: out.sphere },
      ...through.map((at) => ({ shape: 'point' as const, at })),
    ];
  },
  handles3d: ({ inputs: i, params }) =>
    (params.mode === 'inverses' ? CONTROLS : CORNERS).map((k) => ({ handle: k, at: i[k] })),
  drag3d: (handle, to) =>
    (CORNERS as readonly string[]).includes(handle) || (CONTROLS as readonly string[]).includes(handle)
      ? { [handle]: [...to] }
      : {},
});
