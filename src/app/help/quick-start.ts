/**
 * The one-minute quick starts: the (2,3,7) triangle kaleidoscope from an empty canvas in five
 * steps, and a first 3D picture (a sphairahedron's quasi-sphere) in four. One list each for the
 * Help dialog, the README and the end-to-end tests that follow them word by word, so the text a
 * newcomer reads is the text that is proven to work.
 */
export interface QuickStep {
  readonly title: string;
  readonly detail: string;
}

export const QUICK_START: readonly QuickStep[] = [
  {
    title: 'Add a Triangle kaleidoscope',
    detail:
      'Press Space (or double-click the graph), type “triangle” and press Enter. Its p, q, r are 2, 3, 7: the angles π/2, π/3, π/7 of a hyperbolic triangle. The (2,3,7) example the first visit opens has them as 7, 2, 3: p is the corner at the centre, so its seven-fold corner sits in the middle of the disk.',
  },
  {
    title: 'Add a Render node',
    detail: 'Press Space again, type “render”, Enter. Render is where the picture comes from.',
  },
  {
    title: 'Wire the mirrors into Render',
    detail:
      'Drag from the kaleidoscope’s red “mirrors” socket to Render’s “elements” socket. The tessellation appears on the right.',
  },
  {
    title: 'Colour the tiles',
    detail:
      'Add a Tile colouring, wire its “tile” into Render’s “tile”, choose “parity” and pick two colours.',
  },
  {
    title: 'Frame it and keep it',
    detail:
      'Wire the kaleidoscope’s “disk” into Render’s “clip”. Scroll to zoom, drag to pan, then Export → PNG (any size) or Save.',
  },
];

export const QUICK_START_3D: readonly QuickStep[] = [
  {
    title: 'Start with a Sphairahedron',
    detail:
      'Click New, then Add node (or press Space), type “sphairahedron” and press Enter: a polyhedron with spherical faces, turned inside out by an inversion sphere.',
  },
  {
    title: 'Add a Render 3D',
    detail:
      'Add node again, type “render 3d”, Enter. It goes beside the Sphairahedron, and with a Render 3D node the picture becomes a 3D view.',
  },
  {
    title: 'Wire it into Render 3D',
    detail:
      'Drag its “elements” to Render 3D’s “elements” and its “seed” to “seeds”. The quasi-sphere appears: the limit set of the inversions in its faces.',
  },
  {
    title: 'Look around and reshape it',
    detail:
      'Scroll over it to zoom (pinch on a touch screen), drag to orbit, Shift-drag to pan, F to reset. Drag the inversion sphere’s centre (the handle at the top) and the quasi-sphere follows; try another type.',
  },
];
