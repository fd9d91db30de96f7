/**
 * A sphairahedron type's parameter space (paper §5.3, Figs. 30–32): where the shape parameters give
 * a true (ideal, rational) sphairahedron, and what happens outside it — bridges, tunnels, or no
 * shape at all. The derivation: docs/math-3d.md "The parameter space: bridges and tunnels".
 */
import { floorTop, type InfiniteSphairahedron, type OutsideSpace } from './sphairahedron-shared.ts';
import type { SphairahedronType } from './sphairahedron-types.ts';
import { ok, type Result } from './sphere.ts';

export type { OutsideSpace } from './sphairahedron-shared.ts';

/** What the sphairahedron is at a parameter: painted by the parameter-space view. */
export type SpaceClass = 'valid' | 'bridge' | 'tunnel' | 'bridge-tunnel' | 'degenerate';

export const SPACE_CLASSES: readonly SpaceClass[] = [
  'valid',
  'bridge',
  'tunnel',
  'bridge-tunnel',
  'degenerate',
];

/**
 * Completes a shape whose spheres and planes are built: its floor and the reasons it is outside
 * the parameter space (the bridges found by the caller, null where none, and a tunnel when the
 * floor has a hole). Fails only when no sphere covers the floor (degenerate).
 */
export function withOutside(
  shape: Omit<InfiniteSphairahedron, 'floorTop' | 'outside'>,
  bridges: readonly (OutsideSpace | null)[],
): Result<InfiniteSphairahedron> {
  const floor = floorTop(shape.corners, shape.spheres);
  if (!floor.ok) return floor;
  const outside = bridges.filter((b): b is OutsideSpace => b !== null);
  if (floor.value.hole) outside.push({ kind: 'hole' });
  return ok({ ...shape, floorTop: floor.value.top, outside });
}

/** The class of a built shape (valid, bridge, tunnel or both), or of a refused one (degenerate). */
export function spaceClass(shape: Result<InfiniteSphairahedron>): SpaceClass {
  if (!shape.ok) return 'degenerate';
  const bridge = shape.value.outside.some((o) => o.kind === 'bridge');
  const tunnel = shape.value.outside.some((o) => o.kind !== 'bridge');
  return bridge && tunnel ? 'bridge-tunnel' : bridge ? 'bridge' : tunnel ? 'tunnel' : 'valid';
}

/** The node's warning for a shape outside its parameter space: what happens there; null inside. */
export function outsideWarning(type: SphairahedronType, outside: readonly OutsideSpace[]): string | null {
  if (outside.length === 0) return null;
  const parts = outside.map((o) =>
    o.kind === 'hole'
      ? 'a gap opens between the spheres in the floor of the prism: the two sides of the limit set join through it, and the tiling makes tunnels'
      : o.kind === 'bridge'
        ? `sphere ${o.sphere} crosses plane ${o.plane} on the open side (an edge at an angle that is not π/n): its ball overlaps its mirror image, and the tiling makes bridges`
        : `sphere ${o.sphere} crosses plane ${o.plane} under the spheres (an edge at an angle that is not π/n): its ball overlaps its mirror image inside the solid, and the tiling makes tunnels`,
  );
  return `outside the parameter space of ${type.label}: ${parts.join('; ')}. The picture is drawn (an artistic shape, not a Kleinian group's limit set)`;
}
