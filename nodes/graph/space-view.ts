/**
 * Which sphairahedron a document's parameter-space view shows (docs/math-3d.md "The
 * parameter-space view"): the first Sphairahedron parameter space node at the document's top
 * level and the Sphairahedron node wired into it. Read by the render pane (which also writes the
 * wired node's zb, zc on a click) and by the CLI's PNG.
 */
import {
  SPHAIRAHEDRON_TYPE_IDS,
  type SphairahedronType,
  sphairahedronTypeById,
} from '../geometry/space/sphairahedron-types.ts';
import type { GraphDoc } from './document.ts';

export interface SpaceViewTarget {
  /** The Sphairahedron node whose zb, zc the view shows and sets. */
  readonly nodeId: string;
  readonly type: SphairahedronType;
  readonly zb: number;
  readonly zc: number;
  /** zb or zc comes from a wire: a click cannot set it (the wire wins). */
  readonly wired: boolean;
}

export function spaceViewTarget(doc: GraphDoc): SpaceViewTarget | null {
  for (const view of doc.nodes) {
    if (view.type !== 'sphairahedron-space') continue;
    const edge = doc.edges.find((e) => e.to.node === view.id && e.to.port === 'sphairahedron');
    const node = edge && doc.nodes.find((n) => n.id === edge.from.node && n.type === 'sphairahedron');
    if (!node) continue;
    // An unset type is the node's default, the first of the table (cube A).
    const type = sphairahedronTypeById(String(node.params.shape ?? SPHAIRAHEDRON_TYPE_IDS[0]));
    if (!type) continue;
    const wired = doc.edges.some((e) => e.to.node === node.id && (e.to.port === 'zb' || e.to.port === 'zc'));
    return { nodeId: node.id, type, zb: Number(node.params.zb ?? 0), zc: Number(node.params.zc ?? 0), wired };
  }
  return null;
}
