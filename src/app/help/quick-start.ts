/**
 * The one-minute quick start: the (2,3,7) triangle kaleidoscope from an empty canvas in five steps.
 * One list for the Help dialog, the README and the end-to-end test that follows it word by word,
 * so the text a newcomer reads is the text that is proven to work.
 */
export interface QuickStep {
  readonly title: string;
  readonly detail: string;
}

export const QUICK_START: readonly QuickStep[] = [
  {
    title: 'Add a Triangle kaleidoscope',
    detail:
      'Press Space (or double-click the graph), type “triangle” and press Enter. Its p, q, r are 2, 3, 7: the angles π/2, π/3, π/7 of a hyperbolic triangle.',
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
