/**
 * Evaluation: a document → per-node results and the Scene. Nodes run in deterministic topological
 * order; a failing node has no outputs and its dependants say why, the rest go on.
 */
import type { EvalContext, NodeDef, Render3dSettings, RenderSettings } from '../core/define-node.ts';
import { type Diagnostic, diag, hasErrors } from '../core/diagnostics.ts';
import type { HandleItem, OverlayItem } from '../core/overlay.ts';
import { ownEntry, setOwn } from '../core/port-lookup.ts';
import { PORT_TYPE_INFO } from '../core/ports.ts';
import type { NodeRegistry } from '../core/registry.ts';
import { EMPTY_SCENE_DEFAULTS, type Scene } from '../core/scene.ts';
import type { Handle3dItem, Overlay3dItem, Scene3d } from '../core/scene-3d.ts';
import { DEFAULT_TILE } from '../core/tile-spec.ts';
import { type Analysis, analyzeGraph } from './analyze.ts';
import type { GraphDoc, GraphNode } from './document.ts';
import { documentPath, type Flattened, flattenGroups, hasGroups } from './flatten.ts';
import { nodeVersion, nodeVersionProblem } from './migrate.ts';
import { mirrorDiagnostics } from './mirror-check.ts';
import { mutedOutputs } from './mute.ts';
import { nodeName } from './node-names.ts';
import { checkNumber, resolveParams } from './params.ts';

export interface NodeEvaluation {
  readonly outputs?: Readonly<Record<string, unknown>>;
  readonly readout?: string;
  readonly diagnostics: readonly Diagnostic[];
  /** The context evaluate ran with (the editor uses it to map handle drags back to params). */
  readonly ctx?: EvalContext;
  /** The node is muted, or quiet because a required input comes from a muted node (mute.ts). */
  readonly muted?: boolean;
}

/** Node types that draw the picture; a graph should have one (the first by id is drawn). */
export const RENDER_NODE_TYPES: ReadonlySet<string> = new Set(['render', 'render-3d']);

type ChosenRender =
  | { readonly id: string; readonly settings: RenderSettings; readonly settings3d?: undefined }
  | { readonly id: string; readonly settings?: undefined; readonly settings3d: Render3dSettings };

/** The 3D wireframe and handles, gathered like the 2D overlay. */
interface Collected3d {
  readonly overlays: Overlay3dItem[];
  readonly handles: Handle3dItem[];
}

export interface Evaluation {
  /** The plane's picture; empty (no elements, no render node) when the render node is render-3d. */
  readonly scene: Scene;
  /** The 3D picture when the chosen render node is render-3d, else null (2D documents: always). */
  readonly scene3d: Scene3d | null;
  readonly nodes: ReadonlyMap<string, NodeEvaluation>;
  /** Every diagnostic: document structure first, then per node in evaluation order. */
  readonly diagnostics: readonly Diagnostic[];
  readonly analysis: Analysis;
  /**
   * Nodes that came out of groups, by their id in the flattened graph (the keys of `nodes` and the
   * `nodeId` of diagnostics, overlays and handles): their path, group ids from the top (flatten.ts).
   */
  readonly origin: ReadonlyMap<string, readonly string[]>;
}

export interface EvaluateOptions {
  /** Seconds of animation time. */
  readonly time?: number;
}

/** True when every number inside `value` (recursively) is finite. */
export function allFinite(value: unknown, depth = 0): boolean {
  if (typeof value === 'number') return Number.isFinite(value);
  if (depth > 8 || value === null || typeof value !== 'object') return true;
  // Plain loops: this runs on every output of every node, closures here showed in profiles.
  if (Array.isArray(value)) {
    for (const v of value) if (!allFinite(v, depth + 1)) return false;
    return true;
  }
  for (const key in value) {
    if (Object.hasOwn(value, key) && !allFinite((value as Record<string, unknown>)[key], depth + 1))
      return false;
  }
  return true;
}

const NO_ORIGIN: ReadonlyMap<string, readonly string[]> = new Map();

export function evaluateGraph(
  source: GraphDoc,
  registry: NodeRegistry,
  options: EvaluateOptions = {},
): Evaluation {
  // Groups are inlined first: evaluation, the Scene and the shader only ever see a flat graph.
  const flat = hasGroups(source) ? flattenGroups(source) : null;
  const doc = flat?.doc ?? source;
  const origin = flat?.origin ?? NO_ORIGIN;
  const analysis = analyzeGraph(doc, registry);
  const results = new Map<string, NodeEvaluation>();
  const overlays: OverlayItem[] = [];
  const handles: HandleItem[] = [];
  const renders: ChosenRender[] = [];
  const space: Collected3d = { overlays: [], handles: [] };
  const time = options.time ?? 0;

  for (const id of analysis.order) {
    const { node, index, def } = analysis.nodes.get(id)!;
    if (!def) {
      results.set(id, { diagnostics: [] }); // placeholder: reported by analyze
      continue;
    }
    // Documents are migrated once, on load (migrate.ts): a node not at its type's version here is
    // one that could not be migrated, and its params mean something else: it is not run.
    const versionProblem = nodeVersionProblem(def, nodeVersion(node));
    if (versionProblem) {
      const problem = diag('nodeVersion', { nodeId: id, path: `nodes[${index}].version` }, versionProblem);
      results.set(id, { diagnostics: [problem] });
      continue;
    }
    const result = evaluateNode(def, node, index, analysis, results, time);
    results.set(id, result);
    if (!result.ctx) continue;
    if (result.render) renders.push({ id, settings: result.render });
    else if (result.render3d) renders.push({ id, settings3d: result.render3d });
    if (result.ctx.params.visible === false) continue;
    collectOverlay(def, id, node.label, result.ctx, result.outputs, overlays, handles);
    collectOverlay3d(def, id, node.label, result.ctx, result.outputs, space);
  }
  for (const id of analysis.blocked) results.set(id, { diagnostics: [] });

  const diagnostics: Diagnostic[] = [...analysis.diagnostics];
  for (const id of analysis.order) diagnostics.push(...results.get(id)!.diagnostics);

  renders.sort((a, b) => (a.id < b.id ? -1 : a.id > b.id ? 1 : 0));
  const renderNodes = [...analysis.nodes.values()].filter((n) => RENDER_NODE_TYPES.has(n.node.type));
  // A whole-document problem: its path is the document itself (every diagnostic says where).
  if (renderNodes.length === 0 && doc.nodes.length > 0)
    diagnostics.push(diag('noRender', { path: '(document)' }));
  if (renderNodes.length > 1) {
    const used = renders[0]?.id ?? renderNodes.map((n) => n.node.id).sort()[0];
    diagnostics.push(diag('manyRenders', { nodeId: used }, used));
  }
  const first = renders[0];
  // A 3D render leaves the plane's scene empty, so 2D code (compiler, interpreter) never sees 3D data.
  const chosen = first?.settings ? first : undefined;
  const scene: Scene = {
    elements: chosen?.settings.elements ?? [],
    tile: chosen?.settings.tile ?? DEFAULT_TILE,
    maxIterations: chosen?.settings.maxIterations ?? EMPTY_SCENE_DEFAULTS.maxIterations,
    samples: chosen?.settings.samples ?? EMPTY_SCENE_DEFAULTS.samples,
    clip: chosen?.settings.clip ?? null,
    view: { center: doc.view.center, scale: doc.view.scale },
    overlays,
    handles,
    renderNodeId: chosen?.id ?? null,
    ...(chosen?.settings.figures ? { figures: chosen.settings.figures } : {}),
  };
  const scene3d: Scene3d | null = first?.settings3d
    ? { kind: '3d', ...first.settings3d, renderNodeId: first.id, ...space }
    : null;
  // The mirrors' kept sides and corner angles: a wrong picture never comes without a message.
  if (chosen) {
    try {
      diagnostics.push(...mirrorDiagnostics(scene.elements, chosen.id, { analysis, nodes: results }));
    } catch {
      // A check, not the picture: a geometry corner case here must never withhold the render.
    }
  }
  // Flattening's own problems already carry their place in the document.
  const located = flat
    ? [...flat.diagnostics, ...diagnostics.map((d) => inDocument(d, source, flat))]
    : diagnostics;
  return { scene, scene3d, nodes: results, diagnostics: located, analysis, origin };
}

/**
 * A diagnostic of a grouped document with its path in the document, not in the flattened graph:
 * a grouped node's `nodes[i]…` and a grouped (or reconnected) wire's `edges[i]…` become where they
 * live (`nodes[2].group.nodes[0].params.radius`, `nodes[2].group.edges[1]`).
 */
function inDocument(d: Diagnostic, doc: GraphDoc, flat: Flattened): Diagnostic {
  const at = d.path?.match(/^(nodes|edges)\[(\d+)\]/);
  if (!d.path || !at) return d;
  const kind = at[1] as 'nodes' | 'edges';
  const id = flat.doc[kind][Number(at[2])]?.id;
  // A node diagnostic names its node: the index must be that node's (not a neighbour's).
  if (id === undefined || (kind === 'nodes' && d.nodeId !== undefined && d.nodeId !== id)) return d;
  const path = (kind === 'nodes' ? flat.origin : flat.edgeOrigin).get(id);
  const real = path && documentPath(doc, path, kind);
  return real ? { ...d, path: real + d.path.slice(at[0].length) } : d;
}

const NO_EDGES: ReadonlyMap<string, unknown> = new Map();

function evaluateNode(
  def: NodeDef,
  { id: nodeId, params: rawParams, muted }: GraphNode,
  index: number,
  analysis: Analysis,
  results: ReadonlyMap<string, NodeEvaluation>,
  time: number,
): NodeEvaluation & { render?: RenderSettings; render3d?: Render3dSettings } {
  const edgesByPort = analysis.incoming.get(nodeId);
  const resolved = resolveParams(def, { id: nodeId, params: rawParams }, edgesByPort ?? NO_EDGES, [
    'nodes',
    index,
  ]);
  const diagnostics: Diagnostic[] = [...resolved.diagnostics];
  const inputs: Record<string, unknown> = { ...resolved.inline };
  let silenced = false;

  for (const [port, spec] of Object.entries(def.inputs)) {
    const edges = edgesByPort?.get(port);
    const many = PORT_TYPE_INFO[spec.type].many;
    if (!edges) {
      if (many) setOwn(inputs, port, []);
      continue;
    }
    const values: unknown[] = [];
    for (const edge of orderBySource(edges, analysis)) {
      const source = results.get(edge.from.node);
      const value = ownEntry(source?.outputs, edge.from.port);
      if (value === undefined && source?.muted) {
        // A muted source that passes nothing here: a quiet note, and the node itself goes quiet
        // unless the input may be empty — no error cascade (docs/architecture.md "Muted nodes").
        diagnostics.push(
          diag('inputMuted', { nodeId, port }, port, nodeName(analysis.nodes, edge.from.node)),
        );
        if (!many && !spec.optional) silenced = true;
        continue;
      }
      if (value === undefined && source?.outputs) {
        // The source worked but leaves this output empty in its current set-up (a kaleidoscope's
        // disk when it is not hyperbolic): an optional input is then simply unconnected.
        const d = diag(
          'noPortValue',
          { nodeId, port },
          port,
          nodeName(analysis.nodes, edge.from.node),
          edge.from.port,
        );
        diagnostics.push(spec.optional ? d : { ...d, severity: 'error' });
        continue;
      }
      if (value === undefined) {
        // One broken source of a many-input is a warning (the others still draw); otherwise an error.
        const d = diag('upstreamMissing', { nodeId, port }, port, nodeName(analysis.nodes, edge.from.node));
        diagnostics.push(many ? { ...d, severity: 'warning' } : d);
        continue;
      }
      values.push(value);
    }
    // One flat list: an element output is itself a list, a seed output one value (PortInputMap).
    if (many) setOwn(inputs, port, values.flat());
    else if (values.length > 0) {
      setOwn(inputs, port, values[0]);
      if (spec.type === 'number') {
        const problem = checkNumber(spec, values[0] as number);
        if (problem) diagnostics.push(diag('badParam', { nodeId, port }, port, problem));
      }
    }
  }
  if (hasErrors(diagnostics)) return { diagnostics };
  if (muted) return { outputs: mutedOutputs(def, inputs), diagnostics, muted: true };
  if (silenced) return { diagnostics, muted: true };

  const ctx: EvalContext = { nodeId, inputs, params: resolved.params, time };
  let outcome: ReturnType<NodeDef['evaluate']>;
  try {
    outcome = def.evaluate(ctx);
  } catch (e) {
    return {
      diagnostics: [...diagnostics, diag('nodeThrew', { nodeId }, (e as Error)?.message ?? String(e))],
      ctx,
    };
  }
  diagnostics.push(...(outcome.diagnostics ?? []).map((d) => ({ ...d, nodeId })));
  const readout = outcome.readout;
  if (hasErrors(diagnostics) || !outcome.outputs) return { diagnostics, readout, ctx };
  for (const [port, value] of Object.entries(outcome.outputs)) {
    if (!allFinite(value)) {
      diagnostics.push(diag('nonFinite', { nodeId, port }, port));
      return { diagnostics, readout, ctx };
    }
  }
  return {
    outputs: outcome.outputs,
    readout,
    diagnostics,
    ctx,
    render: outcome.render,
    render3d: outcome.render3d,
  };
}

/**
 * Adds a node's overlay shapes and handles. A node that failed (e.g. three collinear points) still
 * offers the handles that depend only on its inputs, so the user can drag it back into shape;
 * shapes and handles that need the missing outputs throw and are skipped.
 */
function collectOverlay(
  def: NodeDef,
  id: string,
  label: string | undefined,
  ctx: EvalContext,
  outputs: Readonly<Record<string, unknown>> | undefined,
  overlays: OverlayItem[],
  handles: HandleItem[],
): void {
  if (outputs) {
    attempt(() => {
      for (const shape of def.overlay?.(ctx, outputs) ?? []) {
        if (allFinite(shape))
          overlays.push({ nodeId: id, color: def.color, shape, ...(label ? { label } : {}) });
      }
    });
  }
  attempt(() => {
    for (const h of def.handles?.(ctx, outputs ?? {}) ?? []) {
      if (Array.isArray(h.at) && allFinite(h.at)) handles.push({ ...h, nodeId: id });
    }
  });
}

/** Runs an overlay callback: an overlay is decoration, a failure here must not hide the node's result. */
function attempt(f: () => void): void {
  try {
    f();
  } catch {
    // skipped: see above
  }
}

/** The 3D counterpart of collectOverlay (nodes with `overlay3d` / `handles3d`). */
function collectOverlay3d(
  def: NodeDef,
  id: string,
  label: string | undefined,
  ctx: EvalContext,
  outputs: Readonly<Record<string, unknown>> | undefined,
  into: Collected3d,
): void {
  if (outputs && def.overlay3d) {
    attempt(() => {
      for (const shape of def.overlay3d?.(ctx, outputs) ?? []) {
        if (allFinite(shape))
          into.overlays.push({ nodeId: id, color: def.color, shape, ...(label ? { label } : {}) });
      }
    });
  }
  if (def.handles3d) {
    attempt(() => {
      for (const h of def.handles3d?.(ctx, outputs ?? {}) ?? []) {
        if (Array.isArray(h.at) && h.at.length === 3 && allFinite(h.at))
          into.handles.push({ ...h, nodeId: id });
      }
    });
  }
}

/** Edges into a many-input, ordered by their source node's evaluation order ("graph order"). */
function orderBySource<T extends { from: { node: string } }>(edges: readonly T[], analysis: Analysis): T[] {
  if (edges.length < 2) return [...edges];
  const rank = new Map(analysis.order.map((id, i) => [id, i]));
  return [...edges].sort((a, b) => (rank.get(a.from.node) ?? 0) - (rank.get(b.from.node) ?? 0));
}
