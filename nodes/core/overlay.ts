/** What the overlay draws over the render for each node, and the handles a user can drag. */
import type { Circle, Line, Vec2 } from './values.ts';

/** What the overlay draws for a node (in the node's colour), with its draggable handles. */
export type OverlayShape =
  | { readonly shape: 'point'; readonly at: Vec2 }
  | { readonly shape: 'line'; readonly line: Line }
  | { readonly shape: 'circle'; readonly circle: Circle };

export interface OverlayItem {
  readonly nodeId: string;
  readonly color: string;
  readonly label?: string;
  readonly shape: OverlayShape;
}

export interface HandleItem {
  readonly nodeId: string;
  /** Handle id, unique within the node, passed back to the node type's `drag`. */
  readonly handle: string;
  readonly at: Vec2;
  /**
   * A click (press and release without moving) on empty space in the render places this handle
   * there, as one undo step, while a drag on empty space still pans (the maskit-slice's μ).
   */
  readonly placeOnClick?: boolean;
}
