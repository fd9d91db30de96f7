/**
 * The parameter-space view's classes at pane resolution (paper Fig. 30): a sphairahedron type's
 * (zb, zc) plane — the zb axis for types with zb only — with each pixel the class of the shape
 * built at its centre (docs/math-3d.md "The parameter-space view"). One construction costs
 * about 0.1–0.3 ms, so not every pixel is built: a quadtree of blocks, each built at its four
 * corners, fills a block whose corners agree and splits one whose corners differ, down to single
 * pixels. Then the boundary is traced: a built pixel next to a filled one of another class builds
 * that one, and so on from each pixel built, so a region that bulges into a filled block is found
 * from where it touches a built pixel. Every pixel next to a class change is therefore built
 * itself: the boundary is exact per pixel. (An island touching no built pixel can be missed, such
 * as a lone pixel of the classifier's sampling speckle near a boundary.)
 * The work comes in steps, so the app can show the picture sharpening and stay responsive.
 */
import { pixelToWorld, type View } from '../../core/view.ts';
import { infiniteSphairahedron } from './sphairahedron.ts';
import { SPACE_CLASSES, spaceClass } from './sphairahedron-space.ts';
import type { SphairahedronType } from './sphairahedron-types.ts';

/** A pixel not painted yet. */
export const UNPAINTED = 255;
/** The coarsest block side in pixels: a power of two. */
const BLOCK = 16;

/** Whether the type has the zc parameter (cube types); prisms and cakes have zb only. */
export const hasZc = (type: SphairahedronType): boolean => type.kind === 'cube';

/** The class (an index into SPACE_CLASSES) of the type's shape at (zb, zc); zc is ignored without it. */
export function spaceClassIndex(type: SphairahedronType, zb: number, zc: number): number {
  return SPACE_CLASSES.indexOf(spaceClass(infiniteSphairahedron(type, zb, hasZc(type) ? zc : 0)));
}

/**
 * The (zb, zc) at the centre of pixel (x, y) (row 0 at the top) of a width × height picture of
 * `view`: the same map as the 2D render's (nodes/core/view.ts), zb to the right, zc up.
 */
export function spacePixelParam(view: View, width: number, height: number, x: number, y: number) {
  return pixelToWorld(view, width, height, x, height - 1 - y);
}

/** The classes of a width × height picture of `view`, computed a step at a time. */
export class SpacePainter {
  /** Per pixel, row 0 at the top: an index into SPACE_CLASSES, or UNPAINTED. */
  readonly classes: Uint8Array;
  /** Constructions made so far. */
  builds = 0;
  /** Built classes on the lattice of pixel corners (zb-only types: one per column), UNPAINTED if not built. */
  private readonly built: Uint8Array;
  private readonly stride: number;
  private readonly oneD: boolean;
  /** Blocks to visit, breadth first (coarse before fine): x, y, side. */
  private readonly queue: number[] = [];
  private next = 0;
  /** After the quadtree: built pixels (x + y·width) whose neighbours are still to be compared. */
  private trace: number[] | null = null;

  constructor(
    private readonly type: SphairahedronType,
    private readonly view: View,
    readonly width: number,
    readonly height: number,
  ) {
    this.classes = new Uint8Array(width * height).fill(UNPAINTED);
    this.oneD = !hasZc(type);
    // The lattice covers the picture with whole blocks (its far corners may lie past the edge).
    const gw = Math.max(1, Math.ceil((width - 1) / BLOCK)) * BLOCK;
    const gh = Math.max(1, Math.ceil((height - 1) / BLOCK)) * BLOCK;
    this.stride = gw + 1;
    this.built = new Uint8Array(this.oneD ? gw + 1 : (gw + 1) * (gh + 1)).fill(UNPAINTED);
    for (let y = 0; y < gh; y += BLOCK) for (let x = 0; x < gw; x += BLOCK) this.queue.push(x, y, BLOCK);
  }

  get done(): boolean {
    return this.trace !== null && this.trace.length === 0;
  }

  /** Visits blocks until about `maxBuilds` more shapes were built (or all is done); returns done. */
  step(maxBuilds: number): boolean {
    const limit = this.builds + maxBuilds;
    while (!this.done && this.builds < limit) {
      if (this.next < this.queue.length) {
        const x = this.queue[this.next++]!;
        const y = this.queue[this.next++]!;
        const s = this.queue[this.next++]!;
        this.visit(x, y, s);
      } else if (this.trace === null) {
        this.queue.length = this.next = 0;
        this.trace = [];
        for (let p = 0; p < this.width * this.height; p++) if (this.isBuilt(p)) this.trace.push(p);
      } else this.compareNeighbours(this.trace.pop()!);
    }
    return this.done;
  }

  private isBuilt(p: number): boolean {
    const x = p % this.width;
    const y = (p - x) / this.width;
    return this.built[this.oneD ? x : y * this.stride + x] !== UNPAINTED;
  }

  /** Builds each filled neighbour of built pixel p that shows another class, and traces on from it. */
  private compareNeighbours(p: number): void {
    const x = p % this.width;
    const y = (p - x) / this.width;
    const c = this.classes[p];
    const near: [number, number][] = [
      [x - 1, y],
      [x + 1, y],
      [x, y - 1],
      [x, y + 1],
    ];
    for (const [nx, ny] of near) {
      if (nx < 0 || ny < 0 || nx >= this.width || ny >= this.height) continue;
      const q = ny * this.width + nx;
      if (this.classes[q] === c || this.isBuilt(q)) continue;
      this.at(nx, ny);
      this.trace!.push(q);
    }
  }

  /** The class at pixel corner-lattice point (x, y), built once. */
  private at(x: number, y: number): number {
    const key = this.oneD ? x : y * this.stride + x;
    let c = this.built[key]!;
    if (c === UNPAINTED) {
      const [zb, zc] = spacePixelParam(this.view, this.width, this.height, x, y);
      c = spaceClassIndex(this.type, zb, zc);
      this.built[key] = c;
      this.builds++;
    }
    if (x < this.width && y < this.height) this.classes[y * this.width + x] = c;
    return c;
  }

  private visit(x: number, y: number, s: number): void {
    const a = this.at(x, y);
    const b = this.at(x + s, y);
    const c = this.at(x, y + s);
    const d = this.at(x + s, y + s);
    if (s === 1) return;
    const h = s / 2;
    if (a === b && a === c && a === d) {
      this.fill(x, y, s, s, a);
      return;
    }
    // Until the quarters are visited, each shows its own corner's class.
    this.fill(x, y, h, h, a);
    this.fill(x + h, y, h, h, b);
    this.fill(x, y + h, h, h, c);
    this.fill(x + h, y + h, h, h, d);
    this.queue.push(x, y, h, x + h, y, h, x, y + h, h, x + h, y + h, h);
  }

  /** Fills the pixels of a block (its far edge included) with c, those built exactly with their own. */
  private fill(x0: number, y0: number, w: number, h: number, c: number): void {
    const x1 = Math.min(x0 + w, this.width - 1);
    const y1 = Math.min(y0 + h, this.height - 1);
    for (let y = y0; y <= y1; y++)
      for (let x = x0; x <= x1; x++) {
        const built = this.built[this.oneD ? x : y * this.stride + x]!;
        this.classes[y * this.width + x] = built === UNPAINTED ? c : built;
      }
  }
}

/** All of a picture's classes at once (the CLI and tests; the app paints in steps). */
export function paintSpace(type: SphairahedronType, view: View, width: number, height: number): Uint8Array {
  const painter = new SpacePainter(type, view, width, height);
  painter.step(Number.POSITIVE_INFINITY);
  return painter.classes;
}
