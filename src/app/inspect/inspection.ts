/**
 * "Explain this pixel", the model behind the panel and the orbit drawn on the overlay: the CPU
 * trace of what the picture does at the pixel's centre (shader-gen/trace.ts tracePicture), the
 * word of elements applied, named for people (nodes/graph/element-names.ts), the sentence saying
 * why the run stopped, and the GPU's depth at the same pixel compared with it — a disagreement is
 * reported with its likely cause (the path passes within float32 rounding of a mirror).
 */

import { elementNames } from '../../../nodes/graph/element-names.ts';
import type { Evaluation } from '../../../nodes/graph/evaluate.ts';
import { prepare } from '../../../shader-gen/interpret.ts';
import { pathMargin } from '../../../shader-gen/path-margin.ts';
import { type IisTrace, type StopReason, tracePicture } from '../../../shader-gen/trace.ts';
import type { PixelInspection } from '../../viewport/pixel-probe.ts';

export interface WordLetter {
  /** 1-based step number (the marker's number on the overlay). */
  readonly step: number;
  readonly name: string;
  readonly nodeId: string;
  readonly color: string;
  /** Depth this step adds: 1, or k for a closed-form fold by k (written as a power). */
  readonly power: number;
  readonly at: readonly [number, number];
  readonly factor: number;
}

export type GpuCheck =
  | { readonly kind: 'agrees'; readonly depth: number }
  | { readonly kind: 'disagrees'; readonly depth: number; readonly stop: StopReason; readonly note: string }
  | { readonly kind: 'unavailable'; readonly reason: string };

export interface Inspection {
  readonly trace: IisTrace;
  readonly word: readonly WordLetter[];
  readonly stopText: string;
  readonly gpu: GpuCheck;
  readonly maxIterations: number;
}

/** Float32 carries about 7 digits: a path closer than this (relative to the view) may branch otherwise. */
const FLOAT32_MARGIN = 1e-5;

const FALLBACK_COLOR = '#ffffff';
/**
 * The mirrors of one node (a kaleidoscope's three) share its colour on the construction, but the
 * orbit must tell them apart: they take these, in order (the logo's three first).
 */
const SIBLING_COLORS = ['#f2c14e', '#5b8def', '#e85d75', '#6cc7a0', '#b58cf0', '#f08c5b'];

/** Each element's colour on the orbit: its node's, or a sibling colour when the node gives several. */
export function elementColors(
  elements: readonly { readonly nodeId: string }[],
  analysis: Evaluation['analysis'],
): string[] {
  const perNode = new Map<string, number>();
  for (const e of elements) perNode.set(e.nodeId, (perNode.get(e.nodeId) ?? 0) + 1);
  const seen = new Map<string, number>();
  return elements.map(({ nodeId }) => {
    const k = seen.get(nodeId) ?? 0;
    seen.set(nodeId, k + 1);
    if ((perNode.get(nodeId) ?? 1) > 1) return SIBLING_COLORS[k % SIBLING_COLORS.length];
    return analysis.nodes.get(nodeId)?.def?.color ?? FALLBACK_COLOR;
  });
}

export function stopSentence(t: IisTrace, maxIterations: number, seedName: string | null): string {
  const steps = `${t.depth} step${t.depth === 1 ? '' : 's'}`;
  switch (t.stop) {
    case 'fundamental-domain':
      return t.depth === 0
        ? 'Already in the tile (the fundamental domain): no mirror holds this point.'
        : `Reached the tile (the fundamental domain) after ${steps}.`;
    case 'limit':
      return `Hit the limit: still inside an element after ${steps} (max iterations ${maxIterations}), so it is on or very near the limit set.`;
    case 'seed':
      return `Landed in the orbit seed ${seedName ? `“${seedName}” ` : ''}after ${steps}: the pixel shows the seed.`;
    case 'clipped':
      return 'Outside the clip disk: the picture shows the background here, and no step is taken.';
  }
}

export function inspect(evaluation: Evaluation, probe: PixelInspection): Inspection {
  const { scene, analysis } = evaluation;
  const t = tracePicture(scene, probe.world);
  const names = elementNames(scene.elements, analysis);
  const colors = elementColors(scene.elements, analysis);
  let depth = 0;
  const word = t.steps.map((s, i): WordLetter => {
    const power = s.depth - depth;
    depth = s.depth;
    return {
      step: i + 1,
      name: names[s.element],
      nodeId: s.nodeId,
      color: colors[s.element],
      power,
      at: [s.x, s.y],
      factor: s.factor,
    };
  });
  const seed = t.stop === 'seed' ? scene.tile.seeds?.[t.seed] : undefined;
  const seedNode = seed ? analysis.nodes.get(seed.nodeId) : undefined;
  const seedName = seedNode ? (seedNode.node.label ?? seedNode.def?.label ?? seed!.nodeId) : null;
  return {
    trace: t,
    word,
    stopText: stopSentence(t, scene.maxIterations, seedName),
    gpu: gpuCheck(evaluation, probe, t),
    maxIterations: scene.maxIterations,
  };
}

function gpuCheck(evaluation: Evaluation, probe: PixelInspection, t: IisTrace): GpuCheck {
  if (!probe.gpu.ok) return { kind: 'unavailable', reason: probe.gpu.reason };
  const g = probe.gpu.pixel;
  if (g.depth === t.depth && g.stop === t.stop && g.seed === t.seed)
    return { kind: 'agrees', depth: g.depth };
  const { scene } = evaluation;
  const margin = pathMargin(prepare(scene.elements), scene.maxIterations, probe.world).margin;
  const note =
    margin < FLOAT32_MARGIN * scene.view.scale
      ? 'The path passes within float32 rounding of a mirror, so the GPU (float32) and the CPU (float64) may branch differently here.'
      : 'The path stays clear of the mirrors, so this is not rounding: please report it with the graph.';
  return { kind: 'disagrees', depth: g.depth, stop: g.stop, note };
}
