/**
 * The group's generators as (anti-)Möbius maps, read off the scene's elements: the Cayley graph and
 * the depth-first limit set (docs/math.md "Cayley graph and depth-first limit set") walk words in
 * them. Each element contributes the inverse of its step in each of its regions (the tile in a
 * region R with step s is s⁻¹(F)), so F's neighbours are T_k(F).
 */
import type { SceneElement } from '../core/scene-elements.ts';
import type { Circle, Vec2 } from '../core/values.ts';
import { type AntiMobius, compose, inverse, inversionMap, matrixMap, reflectionMap } from './anti-mobius.ts';
import { cmul, complex, csub } from './complex.ts';

export interface FigureGenerator {
  readonly map: AntiMobius;
  /** Index of the generator that undoes this one (itself for a mirror). */
  readonly inverse: number;
  /**
   * The disk this generator maps the outside of its inverse's disk into (Schottky pairing), or null
   * when its region is not a bounded disk (a half-plane, an outside, a fold).
   */
  readonly disk: Circle | null;
  /** The generator's name: a, b, … and A, B, … for their inverses (Indra's Pearls' convention). */
  readonly name: string;
  /** Index of the generator pair (the Cayley graph's edge colour). */
  readonly pair: number;
  readonly nodeId: string;
}

export type Generators =
  | { readonly ok: true; readonly generators: readonly FigureGenerator[] }
  | { readonly ok: false; readonly message: string; readonly nodeId: string };

const LETTERS = 'abcdefghijklmnopqrstuvwxyz';

/** z ↦ λ(z − c) + c = λz + c(1 − λ). */
const similarity = (lambda: Vec2, c: Vec2): AntiMobius =>
  matrixMap({ a: lambda, b: csub(c, cmul(c, lambda)), c: complex(0), d: complex(1) });

/** z ↦ z + s. */
const translation = (s: Vec2): AntiMobius => matrixMap({ a: complex(1), b: s, c: complex(0), d: complex(1) });

const disk = (r: { c: Vec2; r: number; outside: boolean }): Circle | null =>
  r.outside ? null : { c: r.c, r: r.r };

/** The inverse steps of one element: [map, disk] per region; a pair when the two undo each other. */
function elementMaps(e: SceneElement): { maps: [AntiMobius, Circle | null][]; involutions: boolean } | null {
  switch (e.kind) {
    case 'inversion':
      return { maps: [[inversionMap(e), { c: e.c, r: e.r }]], involutions: true };
    case 'outer-inversion':
      return { maps: [[inversionMap(e), null]], involutions: true };
    case 'reflection':
      return { maps: [[reflectionMap(e.q, e.n), null]], involutions: true };
    case 'parallel-mirrors': {
      const far: Vec2 = [e.q[0] + e.period * e.n[0], e.q[1] + e.period * e.n[1]];
      return {
        maps: [
          [reflectionMap(e.q, e.n), null],
          [reflectionMap(far, e.n), null],
        ],
        involutions: true,
      };
    }
    case 'mobius': {
      // Step in A: g = σ_C2∘σ_C1, so the tile in A is g⁻¹(F) = σ_C1∘σ_C2(F); in B it is g(F).
      const g = compose(inversionMap(e.c2), inversionMap(e.c1));
      return {
        maps: [
          [inverse(g), disk(e.a)],
          [g, disk(e.b)],
        ],
        involutions: false,
      };
    }
    case 'mobius-matrix': {
      const g = matrixMap(e);
      return {
        maps: [
          [inverse(g), disk(e.forward)],
          [g, disk(e.backward)],
        ],
        involutions: false,
      };
    }
    case 'rotation': {
      const t = (2 * Math.PI) / e.order;
      const r = similarity([Math.cos(t), Math.sin(t)], e.c);
      return {
        maps: [
          [r, null],
          [inverse(r), null],
        ],
        involutions: false,
      };
    }
    case 'translation': {
      const t = translation(e.shift ?? [e.period * e.n[0], e.period * e.n[1]]);
      return {
        maps: [
          [t, null],
          [inverse(t), null],
        ],
        involutions: false,
      };
    }
    case 'glide-reflection': {
      // Translate by period·n, then reflect in the axis through q along n (normal n⊥).
      const g = compose(
        reflectionMap(e.q, [-e.n[1], e.n[0]]),
        translation([e.period * e.n[0], e.period * e.n[1]]),
      );
      return {
        maps: [
          [g, null],
          [inverse(g), null],
        ],
        involutions: false,
      };
    }
    case 'spiral-similarity': {
      const k = (e.r2 / e.r1) ** 2;
      const s = similarity([k * Math.cos(2 * e.angle), k * Math.sin(2 * e.angle)], e.c);
      return {
        maps: [
          [s, null],
          [inverse(s), null],
        ],
        involutions: false,
      };
    }
    default:
      return null;
  }
}

const KIND_NAMES: Partial<Record<SceneElement['kind'], string>> = {
  loxodromic: 'a loxodromic generator',
  maskit: 'a Maskit group',
  'maskit-slice': 'the Maskit slice (a picture of parameters, not of a group)',
};

/** Every element's generators in graph order, or the first element that has none. */
export function sceneGenerators(scene: { readonly elements: readonly SceneElement[] }): Generators {
  const generators: FigureGenerator[] = [];
  let pair = 0;
  for (const e of scene.elements) {
    const parts = elementMaps(e);
    if (!parts) {
      return {
        ok: false,
        nodeId: e.nodeId,
        message: `node "${e.nodeId}" is ${KIND_NAMES[e.kind] ?? e.kind}: the Cayley graph and the depth-first limit set take mirrors, Möbius generators and folds only`,
      };
    }
    const base = generators.length;
    parts.maps.forEach(([map, d], i) => {
      const letter = LETTERS[pair % LETTERS.length] ?? 'g';
      const isInverse = !parts.involutions && i === 1;
      generators.push({
        map,
        disk: d,
        inverse: parts.involutions ? base + i : base + 1 - i,
        name: isInverse ? letter.toUpperCase() : letter,
        pair,
        nodeId: e.nodeId,
      });
      if (parts.involutions || i === 1) pair++;
    });
  }
  return { ok: true, generators };
}

export type SchottkyDisks =
  | { readonly ok: true; readonly disks: readonly Circle[] }
  | { readonly ok: false; readonly message: string; readonly nodeId?: string };

/**
 * The generators' disks when the group is Schottky-type (docs/math.md "Cayley graph and
 * depth-first limit set"): at least two generators, each with a bounded disk, no two disks
 * overlapping (tangent is fine: a relative 10⁻⁶ of slack). Else why not, naming the node.
 */
export function schottkyDisks(gens: readonly FigureGenerator[]): SchottkyDisks {
  if (gens.length < 2)
    return { ok: false, message: 'the depth-first limit set needs at least two generators' };
  const disks: Circle[] = [];
  for (const g of gens) {
    if (!g.disk)
      return {
        ok: false,
        nodeId: g.nodeId,
        message: `node "${g.nodeId}" acts outside a bounded disk (a line, an outside or a fold): the depth-first limit set takes inversions and Möbius generators whose disks are disjoint`,
      };
    disks.push(g.disk);
  }
  for (let i = 0; i < disks.length; i++)
    for (let j = i + 1; j < disks.length; j++) {
      const d = Math.hypot(disks[i].c[0] - disks[j].c[0], disks[i].c[1] - disks[j].c[1]);
      if (d < (disks[i].r + disks[j].r) * (1 - 1e-6))
        return {
          ok: false,
          nodeId: gens[j].nodeId,
          message: `the disks of "${gens[i].nodeId}" (${gens[i].name}) and "${gens[j].nodeId}" (${gens[j].name}) overlap: the depth-first search draws Schottky-type groups, whose disks are disjoint or tangent`,
        };
    }
  return { ok: true, disks };
}
