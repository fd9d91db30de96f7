/**
 * One frame of an animation on the CPU: the graph evaluated at time t, rasterized at the full
 * sample count. Frames depend on nothing but (graph, t, size, samples), so any frame can be
 * rendered alone, on any thread or machine, and match the sequence byte for byte.
 */
import { hasErrors } from '../../nodes/core/diagnostics.ts';
import type { Scene } from '../../nodes/core/scene.ts';
import type { GraphDoc } from '../../nodes/graph/document.ts';
import { evaluateGraph } from '../../nodes/graph/evaluate.ts';
import { registry } from '../../nodes/types/index.ts';
import { type Raster, rasterize } from '../../shader-gen/raster.ts';
import { CliError } from './command.ts';
import { scenePictures } from './scene-pictures.ts';

export interface FrameRequest {
  readonly width: number;
  readonly height: number;
  /** Samples per pixel; the render node's setting when absent. */
  readonly samples?: number;
}

/** The scene of `doc` at `time` seconds. A graph that fails at that time is an error, not a blank frame. */
export function sceneAt(doc: GraphDoc, time: number): Scene {
  const evaluation = evaluateGraph(doc, registry, { time });
  if (hasErrors(evaluation.diagnostics) || evaluation.scene.renderNodeId === null) {
    const first = evaluation.diagnostics.find((d) => d.severity === 'error');
    throw new CliError(`at time ${time} s the graph has errors${first ? `: ${first.message}` : ''}`);
  }
  return evaluation.scene;
}

export function renderFrameAt(doc: GraphDoc, time: number, request: FrameRequest): Raster {
  const scene = sceneAt(doc, time);
  return rasterize(scene, { pictures: scenePictures(scene), ...request });
}
