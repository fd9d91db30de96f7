/**
 * The IIS elements of a Scene: each kind's data, with every construction already done. Element
 * kinds are implemented (CPU + GLSL, side by side) in shader-gen/elements/.
 */
import type { Circle, Vec2 } from './values.ts';

export interface DiskRegion {
  readonly c: Vec2;
  readonly r: number;
  readonly outside: boolean;
}

interface ElementBase {
  /** The node that produced the element: errors and `#line` markers point back to it. */
  readonly nodeId: string;
}

/** Inversion in the circle (c, r): inside |p−c| < r, σ(p) = c + r²(p−c)/|p−c|². */
export interface InversionElement extends ElementBase {
  readonly kind: 'inversion';
  readonly c: Vec2;
  readonly r: number;
}

/**
 * Inversion in the circle (c, r) that keeps the inside (a flipped circle mirror): it acts where
 * |p−c| > r, σ(p) = c + r²(p−c)/|p−c|².
 */
export interface OuterInversionElement extends ElementBase {
  readonly kind: 'outer-inversion';
  readonly c: Vec2;
  readonly r: number;
}

/** Reflection in the line through q with unit normal n: inside (p−q)·n < 0. */
export interface ReflectionElement extends ElementBase {
  readonly kind: 'reflection';
  readonly q: Vec2;
  readonly n: Vec2;
}

/**
 * Two-circle Möbius generator g = σ_C2∘σ_C1 (docs/math.md). In A apply g, else in B apply
 * g⁻¹ = σ_C1∘σ_C2; A is always tested first. A is bounded by C1, B by C1' = σ_C2(C1).
 */
export interface MobiusElement extends ElementBase {
  readonly kind: 'mobius';
  readonly c1: Circle;
  readonly c2: Circle;
  readonly a: DiskRegion;
  readonly b: DiskRegion;
}

/**
 * Loxodromic generator from two nested circles and a control point (docs/math.md): inside A (C1)
 * p ← σ_C2(σ_C1(σ_C3(ρ_L(p)))); inside B (outside C1') p ← ρ_L(σ_C3(σ_C1(σ_C2(p)))).
 */
export interface LoxodromicElement extends ElementBase {
  readonly kind: 'loxodromic';
  readonly c1: Circle;
  readonly c2: Circle;
  readonly c3: Circle;
  /** ρ_L: reflection in the line through c1 and c2 (q, unit normal n). */
  readonly lq: Vec2;
  readonly ln: Vec2;
  readonly a: DiskRegion;
  readonly b: DiskRegion;
}

/**
 * Möbius map from a det-1 matrix (docs/math.md "Möbius from a matrix"), complex entries as [re, im]:
 * inside I(g) (`forward`, centre −d/c) apply g(z) = (az + b)/(cz + d); else inside I(g⁻¹)
 * (`backward`, centre a/c) apply g⁻¹(z) = (dz − b)/(−cz + a). Both radii are 1/|c|.
 */
export interface MobiusMatrixElement extends ElementBase {
  readonly kind: 'mobius-matrix';
  readonly a: Vec2;
  readonly b: Vec2;
  readonly c: Vec2;
  readonly d: Vec2;
  readonly forward: DiskRegion;
  readonly backward: DiskRegion;
}

/** A strip across the unit direction n: h = (p−q)·n, tile 0 ≤ h < period (closed-form kinds). */
export interface StripData {
  readonly q: Vec2;
  readonly n: Vec2;
  readonly period: number;
}

/**
 * Translation by `shift` (default period·n), folded in closed form: p ← p − ⌊h/D⌋·shift. An
 * oblique shift (shift·n = period, not along n) lets two strips make any lattice: each strip's
 * normal is perpendicular to the other's shift, so neither fold changes the other's h.
 */
export interface TranslationElement extends ElementBase, StripData {
  readonly kind: 'translation';
  readonly shift?: Vec2;
}

/** The reflections in the parallel lines h = 0 and h = period, folded in closed form. */
export interface ParallelMirrorsElement extends ElementBase, StripData {
  readonly kind: 'parallel-mirrors';
}

/** Glide: translate by period·n and reflect in the axis through q along n, in closed form. */
export interface GlideReflectionElement extends ElementBase, StripData {
  readonly kind: 'glide-reflection';
}

/** Rotation by 2π/order about c; tile = the wedge from unit direction b1 counter-clockwise. */
export interface RotationElement extends ElementBase {
  readonly kind: 'rotation';
  readonly c: Vec2;
  readonly b1: Vec2;
  readonly order: number;
}

/**
 * Spiral similarity g(p) = c + (r2/r1)² R_2φ (p − c) (φ = `angle`, radians; 0 < r1 < r2); tile =
 * the annulus r1 ≤ |p − c| < r2²/r1, folded in closed form.
 */
export interface SpiralSimilarityElement extends ElementBase {
  readonly kind: 'spiral-similarity';
  readonly c: Vec2;
  readonly r1: number;
  readonly r2: number;
  readonly angle: number;
}

/**
 * The Maskit group of parameter μ (docs/math.md "The Maskit slice"): a(z) = μ + 1/z and
 * b(z) = z + 2, drawn by the isometric circles |z − 2k| = 1 (of a) and |z − μ − 2k| = 1 (of a⁻¹)
 * in the strip 0 < Im z < Im μ; `mu` = (Re μ, Im μ) with Im μ > 0.
 */
export interface MaskitElement extends ElementBase {
  readonly kind: 'maskit';
  readonly mu: Vec2;
}

/**
 * The Maskit slice drawn in the parameter plane (docs/math.md "The Maskit slice boundary"): the
 * point of the picture is μ, and its inside is the complement of the slice — below the polyline
 * through the cusps of denominator ≤ `maxDenominator` (periodic in Re μ, mirrored in Im μ = 0).
 */
export interface MaskitSliceElement extends ElementBase {
  readonly kind: 'maskit-slice';
  readonly maxDenominator: number;
}

export type SceneElement =
  | InversionElement
  | OuterInversionElement
  | ReflectionElement
  | MobiusElement
  | LoxodromicElement
  | MobiusMatrixElement
  | TranslationElement
  | ParallelMirrorsElement
  | GlideReflectionElement
  | RotationElement
  | SpiralSimilarityElement
  | MaskitElement
  | MaskitSliceElement;
export type ElementKind = SceneElement['kind'];
