/**
 * Warnings of the 3D render node about where things sit in the IIS regions (docs/math-3d.md §7):
 * a camera inside a region the IIS moves or inside a seed, and a seed not in the fundamental domain.
 */
import { type Diagnostic, diag } from '../core/diagnostics.ts';
import { firstBeyond, LIMITS } from '../core/limits.ts';
import type { NodeElement3d, Seed3d, Vec3 } from '../core/scene-3d.ts';
import { seedSamplePoints, seedSignedDistance } from '../core/seed-3d.ts';
import { insideSphere } from '../geometry/space/sphere.ts';
import { elementHolding } from './space-shared.ts';

/**
 * A camera inside an inversion sphere sees the scene turned inside out and shrunken first. (The
 * regions of plane reflections and translations are moved by isometries, and a generator's outer
 * region B may hold every far-away point: a camera there is normal, so those get no warning.)
 * Tested by distance, not by stepping: at the very centre the inversion is undefined.
 */
const holdsCamera = (e: NodeElement3d, camera: Vec3) =>
  e.kind === 'sphere-inversion' && insideSphere(e.sphere, camera);

export function cameraDiagnostics(
  camera: Vec3,
  elements: readonly NodeElement3d[],
  seeds: readonly Seed3d[],
): Diagnostic[] {
  const out: Diagnostic[] = [];
  const holder = elements.find((e) => holdsCamera(e, camera));
  if (holder)
    out.push(
      diag(
        'cameraInside',
        { port: 'camera' },
        `the region of element "${holder.nodeId}"`,
        'the IIS turns that region inside out, so the camera sees a shrunken copy of the scene first (move the camera outside the sphere)',
      ),
    );
  const seed = seeds.find((s) => seedSignedDistance(s, camera) < 0);
  if (seed)
    out.push(
      diag(
        'cameraInside',
        { port: 'camera' },
        `seed "${seed.nodeId}"`,
        'it sees only the inside of that seed',
      ),
    );
  return out;
}

/**
 * The element whose region holds part of the seed: exactly for an inversion sphere (the seed
 * reaches into its ball: signed distance from the mirror's centre below its radius), else by the
 * seed's centre and extreme points.
 */
function holderOf(seed: Seed3d, elements: readonly NodeElement3d[]): NodeElement3d | undefined {
  const mirror = elements.find(
    (e) => e.kind === 'sphere-inversion' && seedSignedDistance(seed, e.sphere.center) < e.sphere.radius,
  );
  if (mirror) return mirror;
  for (const p of seedSamplePoints(seed)) {
    const holder = elementHolding(elements, p);
    if (holder) return holder;
  }
  return undefined;
}

/** One warning per seed that some element's region holds part of (it is not in the fundamental domain). */
export function seedDiagnostics(seeds: readonly Seed3d[], elements: readonly NodeElement3d[]): Diagnostic[] {
  const out: Diagnostic[] = [];
  for (const seed of seeds) {
    if (seed.clipped) continue;
    const holder = holderOf(seed, elements);
    if (holder) out.push(diag('seedOutsideDomain', { port: 'seeds' }, seed.nodeId, holder.nodeId));
  }
  return out;
}

/**
 * KF405, like the 2D compile's check (shader-gen/gpu-range.ts): the first element, seed or camera
 * value beyond LIMITS.gpuMaxMagnitude. The float64 evaluator draws it, but the float32 sphere
 * tracer squares coordinates and radii, and such a value overflows to ∞ there.
 */
export function gpuRangeDiagnostics3d(
  elements: readonly NodeElement3d[],
  seeds: readonly Seed3d[],
  camera: readonly Vec3[] = [],
  max: number = LIMITS.gpuMaxMagnitude,
): Diagnostic[] {
  const far = (port: string, items: readonly unknown[], what: (item: unknown) => string) =>
    items.flatMap((item) => {
      const value = firstBeyond(item, max);
      return value === undefined ? [] : [diag('gpuRange', { port }, value, max, what(item))];
    });
  const named = (kind: string) => (item: unknown) => `${kind} "${(item as { nodeId: string }).nodeId}"`;
  return [
    ...far('elements', elements, named('element')),
    ...far('seeds', seeds, named('seed')),
    ...far('camera', [camera], () => 'the view'),
  ].slice(0, 1);
}
