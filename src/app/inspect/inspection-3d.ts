/**
 * "Explain this pixel" for a 3D graph, the model the same panel shows: the camera ray through the
 * clicked pixel traced on the CPU (shader-gen/space/explain-3d.ts), the hit point, and the word of
 * elements that maps it back onto a seed — named and coloured as in 2D — with the sentence saying
 * how the run ended. The GPU's depth is not read back in 3D: the panel says so.
 */
import type { Camera3d, NodeElement3d, Scene3d, Vec3 } from '../../../nodes/core/scene-3d.ts';
import { elementNames } from '../../../nodes/graph/element-names.ts';
import type { Evaluation } from '../../../nodes/graph/evaluate.ts';
import { explainPixel3d, type PixelTrace3d } from '../../../shader-gen/space/explain-3d.ts';
import { elementColors, type GpuCheck, type WordLetter } from './inspection.ts';

export interface WordLetter3d extends Omit<WordLetter, 'at'> {
  readonly at: Vec3;
}

export interface Inspection3d {
  readonly kind: '3d';
  readonly trace: PixelTrace3d;
  readonly word: readonly WordLetter3d[];
  readonly stopText: string;
  readonly gpu: GpuCheck;
  readonly maxIterations: number;
}

const GPU_3D: GpuCheck = {
  kind: 'unavailable',
  reason:
    'the 3D view is explained by the CPU tracer (the picture’s tested twin); its GPU depth is not read back',
};

const distance = (t: number) => String(+t.toPrecision(3));

/** The sentence for how a 3D pixel's explanation ends. */
function stopSentence3d(t: PixelTrace3d, scene: Scene3d, seedName: string | null): string {
  if (t.stop === 'missed')
    return `The camera ray misses every image of the seeds (${t.marchSteps} march steps): the pixel shows the background.`;
  const ray = `The camera ray hits a surface at distance ${distance(t.t)}. `;
  const steps = `${t.depth} step${t.depth === 1 ? '' : 's'}`;
  if (t.stop === 'limit')
    return `${ray}Its point is still inside an element after ${steps} (max iterations ${scene.maxIterations}): it is on or very near the limit set.`;
  return t.depth === 0
    ? `${ray}It is on the orbit seed ${seedName ? `“${seedName}” ` : ''}itself (no element holds it).`
    : `${ray}Its point is mapped onto the orbit seed ${seedName ? `“${seedName}” ` : ''}in ${steps} (the word below): the pixel shows an image of that seed.`;
}

/**
 * Explains the CSS point (x, y) of a width × height 3D view seen through `camera` (the view's,
 * which may differ from the render node's).
 */
export function inspect3d(
  evaluation: Evaluation,
  scene: Scene3d,
  camera: Camera3d,
  css: readonly [number, number],
  width: number,
  height: number,
): Inspection3d {
  const t = explainPixel3d({ ...scene, camera }, width, height, css[0], height - css[1]);
  const elements = scene.elements as readonly NodeElement3d[];
  const names = elementNames(elements, evaluation.analysis);
  const colors = elementColors(elements, evaluation.analysis);
  let depth = 0;
  const word = t.steps.map((s, i): WordLetter3d => {
    const power = s.depth - depth;
    depth = s.depth;
    const [name, color] = [names[s.element]!, colors[s.element]!];
    return { step: i + 1, name, nodeId: s.nodeId, color, power, at: s.at, factor: s.factor };
  });
  const seed = t.seed >= 0 ? scene.seeds[t.seed] : undefined;
  const seedNode = seed ? evaluation.analysis.nodes.get(seed.nodeId) : undefined;
  const seedName = seedNode ? (seedNode.node.label ?? seedNode.def?.label ?? seed!.nodeId) : null;
  return {
    kind: '3d',
    trace: t,
    word,
    stopText: stopSentence3d(t, scene, seedName),
    gpu: GPU_3D,
    maxIterations: scene.maxIterations,
  };
}
