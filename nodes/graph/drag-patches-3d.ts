/**
 * A 3D handle drag → params patches (pure), the twin of drag-patches.ts for the 3D view. The node
 * type's `drag3d` maps the new handle position to values of its inputs; a value aimed at a WIRED
 * input moves the upstream node that makes it instead, so the construction stays wired:
 * - a point3 goes to the upstream node's first 3D handle (recursively);
 * - a sphere goes to its `center` handle when the centre moved, else its `radius` handle (a point
 *   on the new sphere); a plane to its `point` handle, else its `normal` handle (the normal's tip).
 * Other wired keys are dropped: their value comes from the wire.
 */
import { inputSpec } from '../core/port-lookup.ts';
import type { PortType } from '../core/ports.ts';
import type { Vec3 } from '../core/scene-3d.ts';
import {
  type DragKind,
  type HandleRef,
  MAX_FORWARD_DEPTH,
  type NodePatch,
  walkDrag,
} from './drag-patches.ts';
import type { Evaluation } from './evaluate.ts';

const isVec3 = (v: unknown): v is Vec3 =>
  Array.isArray(v) && v.length === 3 && v.every((x) => typeof x === 'number' && Number.isFinite(x));

const sameVec = (a: Vec3, b: Vec3): boolean => a[0] === b[0] && a[1] === b[1] && a[2] === b[2];

/** The 3D handles a node offers now (hidden nodes included), or none. */
function handlesOf(evaluation: Evaluation, nodeId: string): readonly { handle: string; at: Vec3 }[] {
  const def = evaluation.analysis.nodes.get(nodeId)?.def;
  const result = evaluation.nodes.get(nodeId);
  if (!def?.handles3d || !result?.ctx) return [];
  try {
    return def.handles3d(result.ctx, result.outputs ?? {});
  } catch {
    return [];
  }
}

/**
 * Which handle of the upstream node carries a wired value, and where it goes: see the module
 * comment. `current` is the value the input has now (from the dragged node's evaluation context).
 */
function forwardTarget(
  type: PortType,
  value: unknown,
  current: unknown,
  upstream: readonly { handle: string }[],
): { handle: string; at: Vec3 } | undefined {
  const has = (h: string) => upstream.some((u) => u.handle === h);
  if (type === 'point3')
    return isVec3(value) && upstream[0] ? { handle: upstream[0].handle, at: value } : undefined;
  const v = value as Record<string, unknown> | null;
  const now = current as Record<string, unknown> | undefined;
  if (type === 'sphere' && v && isVec3(v.center) && typeof v.radius === 'number') {
    const moved = !(now && isVec3(now.center) && sameVec(now.center, v.center));
    if (moved) return has('center') ? { handle: 'center', at: v.center } : undefined;
    const rim: Vec3 = [v.center[0] + v.radius, v.center[1], v.center[2]];
    return has('radius') ? { handle: 'radius', at: rim } : undefined;
  }
  if (type === 'plane' && v && isVec3(v.point) && isVec3(v.normal)) {
    const moved = !(now && isVec3(now.point) && sameVec(now.point, v.point));
    if (moved) return has('point') ? { handle: 'point', at: v.point } : undefined;
    const tip: Vec3 = [v.point[0] + v.normal[0], v.point[1] + v.normal[1], v.point[2] + v.normal[2]];
    return has('normal') ? { handle: 'normal', at: tip } : undefined;
  }
  return undefined;
}

/** Space handles: wired point3, sphere and plane inputs move the upstream node (forwardTarget). */
const spaceDrag = (evaluation: Evaluation): DragKind<Vec3> => ({
  drag: (def, handle, at, ctx) => (def.drag3d && isVec3(at) ? def.drag3d(handle, at, ctx) : undefined),
  forward: (def, key, value, ctx, upstream) => {
    const type = inputSpec(def, key)?.type;
    return type && forwardTarget(type, value, ctx.inputs[key], handlesOf(evaluation, upstream));
  },
});

/**
 * The patches that move 3D handle `target` to `to`: the dragged node's own unconnected keys first,
 * then upstream nodes in the order the drag reached them.
 */
export function dragPatches3d(
  evaluation: Evaluation,
  target: HandleRef,
  to: Vec3,
  maxDepth = MAX_FORWARD_DEPTH,
): NodePatch[] {
  return walkDrag(evaluation, spaceDrag(evaluation), target, to, maxDepth);
}
