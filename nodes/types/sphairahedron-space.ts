/**
 * The sphairahedron parameter-space view node (paper Fig. 30): wired to a Sphairahedron node's
 * elements, it makes the render pane (and the CLI's PNG) show that type's (zb, zc) plane painted
 * by what the shape is there — valid, bridges, tunnels, both, no shape — with the current
 * parameter as a red point; a click in the view sets the wired node's (zb, zc). The view itself
 * is src/app/SpaceView.tsx; its pixels nodes/geometry/space/sphairahedron-space-paint.ts.
 * Mathematics: docs/math-3d.md "The parameter-space view".
 */
import { defineNode } from '../core/define-node.ts';
import { element3Input } from './space-shared.ts';

export const sphairahedronSpaceNode = defineNode({
  type: 'sphairahedron-space',
  version: 1,
  label: 'Sphairahedron parameter space',
  category: 'Output',
  color: '#7e57c2',
  // A view, like the render nodes: it has no outputs; its picture is the render pane's (or the PNG's).
  doc: 'A view of the parameter space of the wired Sphairahedron (paper Fig. 30): the plane of its two height parameters (one axis for prisms and cakes) painted by what the shape is there — valid, bridges, tunnels, both, or no shape — with the current parameter as a red point. The render pane shows it beside or instead of the 3D picture; click in it to choose the parameter, drag to pan, wheel to magnify, arrow keys to step.',
  inputs: {
    sphairahedron: {
      ...element3Input('sphairahedron'),
      doc: "wire a Sphairahedron node's elements here: its type and heights are what the view shows and sets",
    },
  },
  outputs: {},
  params: {},
  evaluate: ({ inputs }) => ({
    outputs: {},
    readout:
      inputs.sphairahedron.length === 0
        ? "wire a Sphairahedron node's elements into it to see its parameter space"
        : 'shown in the render pane (Parameter space)',
  }),
});
