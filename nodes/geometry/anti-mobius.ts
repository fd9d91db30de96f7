/**
 * Möbius and anti-Möbius maps of the plane as one value: f(z) = M(z) or f(z) = M(z̄) with M a
 * Möbius matrix (docs/math.md "Cayley graph and depth-first limit set"). Inversions and
 * reflections are anti-Möbius; a chain of them is Möbius when its length is even. Pure float64.
 */
import type { Circle, Vec2 } from '../core/values.ts';
import { cabs, cadd, cconj, cdiv, cmul, complex, cscale, csub } from './complex.ts';
import {
  applyMatrix,
  composeMatrices,
  inverseMatrix,
  inversionMatrix,
  type MobiusMatrix,
  normalizeMatrix,
} from './mobius-matrix.ts';

export interface AntiMobius {
  readonly m: MobiusMatrix;
  /** true: z is conjugated before M applies. */
  readonly anti: boolean;
}

const conjMatrix = (m: MobiusMatrix): MobiusMatrix => ({
  a: cconj(m.a),
  b: cconj(m.b),
  c: cconj(m.c),
  d: cconj(m.d),
});

const unit = (m: MobiusMatrix): MobiusMatrix => normalizeMatrix(m) ?? m;

export const IDENTITY: AntiMobius = {
  m: { a: complex(1), b: complex(0), c: complex(0), d: complex(1) },
  anti: false,
};

/** Inversion in a circle: σ(z) = c + r²/conj(z − c) (mobius-matrix.ts inversionMatrix). */
export const inversionMap = (circle: Circle): AntiMobius => ({
  m: unit(inversionMatrix(circle)),
  anti: true,
});

/**
 * Reflection in the line Re(z n̄) = d (unit normal n, d = q·n): z − 2(Re(z n̄) − d)n = −n² z̄ + 2dn,
 * so M = [[−n², 2dn], [0, 1]].
 */
export function reflectionMap(q: Vec2, n: Vec2): AntiMobius {
  const d = q[0] * n[0] + q[1] * n[1];
  const n2 = cmul(n, n);
  return { m: unit({ a: [-n2[0], -n2[1]], b: cscale(n, 2 * d), c: complex(0), d: complex(1) }), anti: true };
}

/** The holomorphic map of a matrix. */
export const matrixMap = (m: MobiusMatrix): AntiMobius => ({ m: unit(m), anti: false });

/**
 * f∘g (g first): f(g(z)) = F(conj^f(G(conj^g z))); conj(G(w)) = Ḡ(w̄), so the matrix is F·G (F·Ḡ
 * when f is anti) and the result is anti when exactly one of them is.
 */
export const compose = (f: AntiMobius, g: AntiMobius): AntiMobius => ({
  m: unit(composeMatrices(f.m, f.anti ? conjMatrix(g.m) : g.m)),
  anti: f.anti !== g.anti,
});

/** f⁻¹: M⁻¹ when holomorphic; conj(M⁻¹) when anti (z̄ = M⁻¹(w) ⇒ z = conj(M⁻¹)(w̄)). */
export const inverse = (f: AntiMobius): AntiMobius => ({
  m: f.anti ? conjMatrix(inverseMatrix(f.m)) : inverseMatrix(f.m),
  anti: f.anti,
});

/** f(p), or null where f sends p to ∞. */
export const applyMap = (f: AntiMobius, p: Vec2): Vec2 | null => applyMatrix(f.m, f.anti ? cconj(p) : p);

/**
 * Image of the circle (c, r) under f, or null when it goes through the pole (its image is a line).
 * For M (after conjugating c when anti): the point z* = c − r²/conj(c + d/c_M) is the mirror image
 * of the pole −d/c_M in the circle, so M(z*) is the image's centre (the pole's mirror goes to ∞'s
 * mirror); the radius is the distance from it to the image of any point of the circle.
 */
export function imageCircle(f: AntiMobius, k: Circle): Circle | null {
  const c0: Vec2 = f.anti ? cconj(k.c) : k.c;
  const { m } = f;
  let centre: Vec2 | null;
  if (cabs(m.c) === 0) centre = applyMatrix(m, c0);
  else {
    const toPole = cadd(c0, cdiv(m.d, m.c));
    if (cabs(toPole) <= k.r * (1 + 1e-12) && cabs(toPole) >= k.r * (1 - 1e-12)) return null;
    centre = applyMatrix(m, csub(c0, cdiv(complex(k.r * k.r), cconj(toPole))));
  }
  const onCircle = applyMatrix(m, [c0[0] + k.r, c0[1]]);
  if (!centre || !onCircle) return null;
  return { c: centre, r: cabs(csub(onCircle, centre)) };
}
