/**
 * The classroom's step-through: the construction node by node in evaluation order
 * (evaluation.analysis.order, topological with ties by id), and the evaluation as it stands after
 * the first `count` steps — only those nodes' points, lines, circles, handles and mirrors (the
 * hatched kept-side bands the overlay draws from the scene's elements) are there.
 */
import type { Evaluation } from '../../../nodes/graph/evaluate.ts';

export interface ConstructionStep {
  readonly nodeId: string;
  /** The node's own label (user text) or, without one, its type's label. */
  readonly label: string;
  /** The node type's label, e.g. "Circle through 3 points". */
  readonly typeLabel: string;
  /** Whether this node draws something in the overlay (a point, line or circle). */
  readonly drawn: boolean;
}

export function constructionSteps(evaluation: Evaluation): ConstructionStep[] {
  const drawn = new Set(evaluation.scene.overlays.map((o) => o.nodeId));
  return evaluation.analysis.order.map((id) => {
    const entry = evaluation.analysis.nodes.get(id);
    const typeLabel = entry?.def?.label ?? entry?.node.type ?? id;
    return { nodeId: id, label: entry?.node.label ?? typeLabel, typeLabel, drawn: drawn.has(id) };
  });
}

/**
 * The evaluation cut down to the first `count` steps. The mirrors (scene elements) are cut too:
 * the overlay draws each one's hatched band, and a mirror must appear at its own step. The picture
 * is shown only from the Render step on (renderReached), when every mirror it uses is built.
 */
export function evaluationUpTo(
  evaluation: Evaluation,
  steps: readonly ConstructionStep[],
  count: number,
): Evaluation {
  if (count >= steps.length) return evaluation;
  const built = new Set(steps.slice(0, count).map((s) => s.nodeId));
  const scene = evaluation.scene;
  return {
    ...evaluation,
    scene: {
      ...scene,
      elements: scene.elements.filter((e) => built.has(e.nodeId)),
      overlays: scene.overlays.filter((o) => built.has(o.nodeId)),
      handles: scene.handles.filter((h) => built.has(h.nodeId)),
    },
  };
}

/** Whether the render node is among the first `count` steps (then the picture is shown). */
export function renderReached(
  evaluation: Evaluation,
  steps: readonly ConstructionStep[],
  count: number,
): boolean {
  const id = evaluation.scene.renderNodeId;
  if (id === null) return false;
  const at = steps.findIndex((s) => s.nodeId === id);
  return at >= 0 && at < count;
}

/** The depths a class steps the finished picture through (paper Figs. 27–28: steps 1, 2, 5, 20). */
export const GROWTH_DEPTHS = [1, 2, 5, 20] as const;

/**
 * The evaluation drawn with at most `depth` inversions (null: as built): the IIS budget of the 2D
 * scene and of the 3D scene capped, so only what the first `depth` steps reach is drawn — the
 * tiling growing tile by tile, the orbit copy by copy, the sphairahedron's tiles layer by layer
 * (docs/math-3d.md "The tile as a seed"). Only a uniform changes: no shader is recompiled.
 */
export function evaluationToDepth(evaluation: Evaluation, depth: number | null): Evaluation {
  if (depth === null) return evaluation;
  const { scene, scene3d } = evaluation;
  return {
    ...evaluation,
    scene: { ...scene, maxIterations: Math.min(scene.maxIterations, depth) },
    scene3d: scene3d ? { ...scene3d, maxIterations: Math.min(scene3d.maxIterations, depth) } : scene3d,
  };
}
