/**
 * The Kleinflow JSON document (GraphDoc) and its zod schema — the schema is the validator and the
 * source of the published JSON Schema. Per-node params are checked against the node type later
 * (params.ts), because the type decides what they mean.
 */
import { z } from 'zod';
import type { Camera3d } from '../core/scene-3d.ts';
import { DEFAULT_VIEW, type View } from '../core/view.ts';

export const FORMAT = 'kleinflow';
/**
 * Current document version. Older versions migrate forward in migrate.ts. The graph tools' fields
 * (muted, group, frames, via) are optional additions of version 1 (docs/architecture.md "Groups").
 */
export const DOC_VERSION = 1;

const finite = z.number().finite();
const vec2 = z.tuple([finite, finite]);
const id = z.string().min(1, 'expected a non-empty id').max(200, 'ids are at most 200 characters');

export const portRefSchema = z.strictObject({ node: id, port: z.string().min(1).max(200) });

const portName = z.string().min(1).max(200);

/**
 * A reroute point is a dot on a wire: `via` lists the points (graph coordinates) the wire passes
 * through, in order from source to target. Drawing only: evaluation ignores it.
 */
export const edgeSchema = z.strictObject({
  id,
  from: portRefSchema,
  to: portRefSchema,
  via: z.array(vec2).max(100).optional(),
});

/** A group's exposed input: one port of the group node, wired inside to every target. */
export const groupInputSchema = z.strictObject({
  name: portName,
  label: z.string().max(200).optional(),
  targets: z.array(portRefSchema).min(1).max(1000),
});

/** A group's exposed output: one port of the group node, the value of an inner node's output. */
export const groupOutputSchema = z.strictObject({
  name: portName,
  label: z.string().max(200).optional(),
  from: portRefSchema,
});

/** A frame: a titled, coloured backdrop; dragging it moves the nodes inside it. Drawing only. */
export const frameSchema = z.strictObject({
  id,
  title: z.string().max(200),
  color: z.string().regex(/^#[0-9a-fA-F]{6}$/, 'expected a colour "#rrggbb"'),
  position: vec2,
  size: z.tuple([finite.positive(), finite.positive()]),
});

/**
 * A node: a node type with its params, or (type "group") a subgraph of its own nodes and edges
 * with exposed inputs and outputs (docs/architecture.md "Groups"). Inner ids are scoped to the
 * group. `muted` skips the node (docs/architecture.md "Muted nodes").
 */
export const nodeSchema = z.strictObject({
  id,
  type: z.string().min(1).max(200),
  /** Version of the node type the params were written for (1 when absent). */
  version: z.number().int().positive().optional(),
  position: vec2,
  params: z.record(z.string(), z.unknown()),
  label: z.string().max(200).optional(),
  muted: z.boolean().optional(),
  get group() {
    return groupBodySchema.optional();
  },
});

export const groupBodySchema = z.strictObject({
  get nodes() {
    return z.array(nodeSchema);
  },
  edges: z.array(edgeSchema),
  inputs: z.array(groupInputSchema),
  outputs: z.array(groupOutputSchema),
  /** The frames drawn inside the group when it is open (ids scoped to the group). */
  frames: z.array(frameSchema).max(1000).optional(),
});

/** A View (nodes/core/view.ts) as stored in a document. */
export const viewSchema = z.strictObject({
  center: vec2,
  scale: finite.positive('expected a positive number'),
}) satisfies z.ZodType<View>;

const vec3 = z.tuple([finite, finite, finite]);

/**
 * The 3D view's camera (a Camera3d) as the user left it by orbiting, zooming and panning: view
 * state like `view` (saved, never an undo step). Absent: the render-3d node's own camera.
 */
export const camera3dSchema = z.strictObject({
  position: vec3,
  target: vec3,
  fovDeg: finite.gt(0, 'expected an angle above 0°').lt(180, 'expected an angle below 180°'),
}) satisfies z.ZodType<Camera3d>;

/** Limits on the presentation text (docs: README "Presentation"): generous for a lesson, bounded for a URL. */
export const NOTE_MAX_CHARS = 5_000;
export const NOTES_MAX = 500;

/**
 * The presenter's note for each construction step, keyed by node id (plain text or the small
 * Markdown subset the presentation renders as text, never HTML). Notes of deleted nodes are ignored.
 */
export const stepNotesSchema = z
  .record(id, z.string().max(NOTE_MAX_CHARS, `notes are at most ${NOTE_MAX_CHARS} characters`))
  .refine((notes) => Object.keys(notes).length <= NOTES_MAX, `at most ${NOTES_MAX} step notes`)
  .meta({ maxProperties: NOTES_MAX });

export const metaSchema = z
  .object({
    title: z.string().max(500).optional(),
    description: z.string().max(20_000).optional(),
    stepNotes: stepNotesSchema.optional(),
  })
  .catchall(z.unknown());

export const docSchema = z.strictObject({
  format: z.literal(FORMAT),
  version: z.number().int().positive(),
  meta: metaSchema,
  nodes: z.array(nodeSchema),
  edges: z.array(edgeSchema),
  view: viewSchema,
  frames: z.array(frameSchema).max(1000).optional(),
  camera3d: camera3dSchema.optional(),
});

export type GraphDoc = z.infer<typeof docSchema>;
export type GraphNode = z.infer<typeof nodeSchema>;
export type GraphEdge = z.infer<typeof edgeSchema>;
export type PortRef = z.infer<typeof portRefSchema>;
export type GroupBody = z.infer<typeof groupBodySchema>;
export type GraphFrame = z.infer<typeof frameSchema>;

/** A new document's view: a fresh copy of DEFAULT_VIEW (documents are plain mutable JSON). */
export const newDocumentView = (): GraphDoc['view'] => ({
  center: [...DEFAULT_VIEW.center],
  scale: DEFAULT_VIEW.scale,
});

export function emptyDocument(title = 'Untitled'): GraphDoc {
  return {
    format: FORMAT,
    version: DOC_VERSION,
    meta: { title },
    nodes: [],
    edges: [],
    view: newDocumentView(),
  };
}
