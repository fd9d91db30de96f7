/**
 * A node type at version 2 whose migration renames a param, for the tests of "migrate once, on
 * load": version 1 stored the radius as "r", version 2 as "radius". `v1RingDoc` is a version-1
 * document (a ring of radius 2, its inversion, the render) as it would sit in an old file.
 */
import { defineNode } from '../../nodes/core/define-node.ts';
import { createRegistry } from '../../nodes/core/registry.ts';
import type { Circle, Vec2 } from '../../nodes/core/values.ts';
import type { GraphDoc } from '../../nodes/graph/document.ts';
import { evaluateGraph } from '../../nodes/graph/evaluate.ts';
import { registry as appRegistry } from '../../nodes/types/index.ts';
import { doc, edge, node } from '../nodes/support/doc.ts';

export const ring = defineNode({
  type: 'test-ring',
  version: 2,
  label: 'Ring',
  category: 'Geometry',
  color: '#000000',
  doc: 'a circle about the origin',
  inputs: { radius: { type: 'number', label: 'radius', default: 1, min: 0 } },
  outputs: { circle: { type: 'circle' } },
  params: {},
  migrations: { 1: ({ r, ...rest }) => ({ ...rest, radius: r }) },
  evaluate: ({ inputs }) => ({
    outputs: { circle: { c: [0, 0] as Vec2, r: inputs.radius as number } satisfies Circle },
  }),
});

/** The app's node types plus the ring. */
export const ringRegistry = createRegistry([...appRegistry.all, ring]);

export const v1RingDoc = (): GraphDoc =>
  doc(
    [{ ...node('ring', 'test-ring', { r: 2 }), version: 1 }, node('inv', 'inversion'), node('out', 'render')],
    [edge('e1', 'ring.circle', 'inv.circle'), edge('e2', 'inv.element', 'out.elements')],
  );

/** The radius of the inversion circle in the evaluated picture (undefined when there is none). */
export function ringRadius(d: GraphDoc): number | undefined {
  const [element] = evaluateGraph(d, ringRegistry).scene.elements;
  return element?.kind === 'inversion' ? element.r : undefined;
}

/** The ring node of a loaded document is current: version 2, the radius under its new name. */
export const CURRENT_RING = { id: 'ring', type: 'test-ring', version: 2, params: { radius: 2 } };
