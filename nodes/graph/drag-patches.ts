/**
 * A handle drag → params patches (pure). The node type's `drag` maps the new handle position to
 * values of its inputs; a value aimed at a WIRED point input moves the upstream node that makes
 * that point instead (through its first handle, recursively), so the construction stays wired.
 * Other wired keys are dropped: their value comes from the wire.
 */

import type { EvalContext, NodeDef } from '../core/define-node.ts';
import { inputSpec, ownEntry } from '../core/port-lookup.ts';
import { portValueToJson } from '../core/port-values.ts';
import type { Vec2 } from '../core/values.ts';
import type { Evaluation } from './evaluate.ts';

/** New values (document form) for some of a node's params, as the editor applies them. */

/** How many wired point inputs a drag follows upstream (point → circle centre → …). */
export const MAX_FORWARD_DEPTH = 4;

export interface NodePatch {
  nodeId: string;
  params: Record<string, unknown>;
}

export interface HandleRef {
  readonly nodeId: string;
  readonly handle: string;
}

const isVec2 = (v: unknown): v is Vec2 =>
  Array.isArray(v) && v.length === 2 && v.every((x) => typeof x === 'number' && Number.isFinite(x));

/** The first handle a node offers (hidden nodes included), used when a drag is forwarded to it. */
export function firstHandle(evaluation: Evaluation, nodeId: string): string | undefined {
  const def = evaluation.analysis.nodes.get(nodeId)?.def;
  const result = evaluation.nodes.get(nodeId);
  if (!def?.handles || !result?.ctx || !result.outputs) return undefined;
  try {
    return def.handles(result.ctx, result.outputs)[0]?.handle;
  } catch {
    return undefined;
  }
}

/**
 * How one kind of handle drags (the plane's here, space's in drag-patches-3d.ts): the node's own
 * map of a handle position to param values (undefined: the node has no such hook), and where the
 * value of a WIRED input sends the drag upstream (undefined: nowhere, the key is dropped).
 */
export interface DragKind<P> {
  drag(def: NodeDef, handle: string, at: P, ctx: EvalContext): Readonly<Record<string, unknown>> | undefined;
  forward(
    def: NodeDef,
    key: string,
    value: unknown,
    ctx: EvalContext,
    upstream: string,
  ): { handle: string; at: P } | undefined;
}

/**
 * The walk both kinds share: the dragged node's own unconnected keys first, then upstream nodes in
 * the order the drag reached them (at most `maxDepth` wires up).
 */
export function walkDrag<P>(
  evaluation: Evaluation,
  kind: DragKind<P>,
  target: HandleRef,
  to: P,
  maxDepth: number,
): NodePatch[] {
  const byNode = new Map<string, Record<string, unknown>>();
  const visit = (nodeId: string, handle: string, at: P, depth: number) => {
    const def = evaluation.analysis.nodes.get(nodeId)?.def;
    const ctx = evaluation.nodes.get(nodeId)?.ctx;
    if (!def || !ctx) return;
    let patch: Readonly<Record<string, unknown>> | undefined;
    try {
      patch = kind.drag(def, handle, at, ctx);
    } catch {
      return; // a node that cannot follow this position keeps its params
    }
    if (!patch) return;
    const incoming = evaluation.analysis.incoming.get(nodeId);
    for (const [key, value] of Object.entries(patch)) {
      const edge = incoming?.get(key)?.[0];
      if (!edge) {
        const own = byNode.get(nodeId) ?? {};
        own[key] = value;
        byNode.set(nodeId, own);
        continue;
      }
      if (depth >= maxDepth) continue;
      const next = kind.forward(def, key, value, ctx, edge.from.node);
      if (next) visit(edge.from.node, next.handle, next.at, depth + 1);
    }
  };
  visit(target.nodeId, target.handle, to, 0);
  return [...byNode].map(([nodeId, params]) => ({ nodeId, params }));
}

/** Plane handles: a wired point input moves the upstream node through its first handle. */
const planeDrag = (evaluation: Evaluation): DragKind<Vec2> => ({
  drag: (def, handle, at, ctx) => def.drag?.(handle, at, ctx),
  forward: (def, key, value, _ctx, upstream) => {
    if (inputSpec(def, key)?.type !== 'point' || !isVec2(value)) return undefined;
    const handle = firstHandle(evaluation, upstream);
    return handle === undefined ? undefined : { handle, at: value };
  },
});

/**
 * The patches that move `target` to world point `to`: the dragged node's own unconnected keys
 * first, then upstream nodes in the order the drag reached them.
 */
export function dragPatches(
  evaluation: Evaluation,
  target: HandleRef,
  to: Vec2,
  maxDepth = MAX_FORWARD_DEPTH,
): NodePatch[] {
  return walkDrag(evaluation, planeDrag(evaluation), target, to, maxDepth);
}

/**
 * The values the patched keys had before the drag (document form), to put back on Escape. A key
 * the document did not store yet gets the value it evaluated to (its default), which is the same.
 */
export function originalParams(evaluation: Evaluation, patches: readonly NodePatch[]): NodePatch[] {
  return patches.map(({ nodeId, params }) => {
    const entry = evaluation.analysis.nodes.get(nodeId);
    const ctx = evaluation.nodes.get(nodeId)?.ctx;
    const stored = entry?.node.params ?? {};
    const original: Record<string, unknown> = {};
    for (const key of Object.keys(params)) {
      if (Object.hasOwn(stored, key)) original[key] = stored[key];
      else {
        const spec = inputSpec(entry?.def, key);
        const value = ownEntry(spec ? ctx?.inputs : ctx?.params, key);
        original[key] = spec && value !== undefined ? portValueToJson(spec.type, value) : value;
      }
    }
    return { nodeId, params: original };
  });
}
