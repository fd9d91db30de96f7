/**
 * What the render pane says when it has no picture to show, and why. An empty or unfinished graph
 * gets a calm background and says what is missing; an error tone only ever comes with the error
 * itself (the first one found upstream of the Render node, named by its node).
 */
import type { Diagnostic } from '../../nodes/core/diagnostics.ts';
import type { NodeRegistry } from '../../nodes/core/registry.ts';
import type { GraphDoc } from '../../nodes/graph/document.ts';
import { type Evaluation, RENDER_NODE_TYPES } from '../../nodes/graph/evaluate.ts';

export interface RenderHint {
  /** calm: nothing is wrong, the graph is just not finished; error: `text` is the error. */
  readonly tone: 'calm' | 'error';
  readonly text: string;
  /** The node the message is about, for "show me". */
  readonly nodeId?: string;
}

export const HINTS = {
  empty:
    'An empty canvas. Press Space to add a node — a mirror wired into a Render node makes a picture — or open an example.',
  noRender: 'Add a Render node and wire a mirror into its elements to see a picture.',
  noElements:
    'Wire a mirror (a line reflection, a circle inversion or a kaleidoscope) into Render’s elements to see a picture.',
} as const;

/** The hint for this graph, or null when the pane shows a picture. */
export function renderHint(doc: GraphDoc, evaluation: Evaluation, registry: NodeRegistry): RenderHint | null {
  if (doc.nodes.length === 0) return { tone: 'calm', text: HINTS.empty };
  const renders = doc.nodes.filter((n) => RENDER_NODE_TYPES.has(n.type));
  if (renders.length === 0) return { tone: 'calm', text: HINTS.noRender };
  // A 3D render draws whatever it has (its node says when a seed or element is missing).
  if (evaluation.scene3d) return null;
  const { scene } = evaluation;
  if (scene.renderNodeId !== null && scene.elements.length > 0) return null;
  const renderId = scene.renderNodeId ?? renders[0].id;
  const error = firstUpstreamError(doc, evaluation.diagnostics, renderId);
  if (error) {
    const node = doc.nodes.find((n) => n.id === error.nodeId);
    const name = node ? (node.label ?? registry.get(node.type)?.label ?? node.type) : 'the graph';
    return { tone: 'error', text: `No picture: ${name} — ${error.message}`, nodeId: error.nodeId };
  }
  return { tone: 'calm', text: scene.renderNodeId === null ? HINTS.noRender : HINTS.noElements };
}

/** The first error on the Render node or on a node it depends on (breadth-first from Render). */
function firstUpstreamError(
  doc: GraphDoc,
  diagnostics: readonly Diagnostic[],
  renderId: string,
): Diagnostic | undefined {
  const errors = new Map<string, Diagnostic>();
  for (const d of diagnostics)
    if (d.severity === 'error' && d.nodeId !== undefined && !errors.has(d.nodeId)) errors.set(d.nodeId, d);
  const seen = new Set([renderId]);
  const queue = [renderId];
  for (let i = 0; i < queue.length; i++) {
    const found = errors.get(queue[i]);
    if (found) return found;
    for (const e of doc.edges)
      if (e.to.node === queue[i] && !seen.has(e.from.node)) {
        seen.add(e.from.node);
        queue.push(e.from.node);
      }
  }
  return undefined;
}
