/**
 * One numbered table of every message Kleinflow reports. Codes are stable (tests and users may
 * search for them): KF1xx document, KF2xx graph structure, KF3xx node evaluation, KF4xx
 * scene/compile/render, KF5xx import/export.
 */
import type { Vec2 } from './values.ts';

export type Severity = 'error' | 'warning' | 'info';

/**
 * A one-click repair offered with a diagnostic, as data (the UI runs it as ONE undo step):
 * new stored values for some nodes, and/or handle moves applied exactly like a drag in the render
 * (a move aimed at a wired point moves the upstream node that owns it).
 */
export interface DiagnosticFix {
  /** The button's text, e.g. `Flip “AC”`. */
  readonly label: string;
  readonly params?: readonly { readonly nodeId: string; readonly params: Record<string, unknown> }[];
  readonly moves?: readonly { readonly nodeId: string; readonly handle: string; readonly to: Vec2 }[];
}

export interface Diagnostic {
  readonly code: string;
  readonly severity: Severity;
  readonly message: string;
  /** JSON path in the document, e.g. `nodes[3].params.radius`. */
  readonly path?: string;
  readonly nodeId?: string;
  readonly port?: string;
  /**
   * For a text param (a formula): the characters at fault, [start, end) of its text, so the editor
   * can underline them where the person types.
   */
  readonly span?: readonly [number, number];
  readonly fix?: DiagnosticFix;
}

type Entry = {
  readonly code: string;
  readonly severity: Severity;
  readonly text: (...args: never[]) => string;
};

const table = <T extends Record<string, Entry>>(t: T) => t;

export const DIAGNOSTICS = table({
  notJson: { code: 'KF101', severity: 'error', text: (detail: string) => `not valid JSON: ${detail}` },
  schema: { code: 'KF102', severity: 'error', text: (detail: string) => detail },
  wrongFormat: {
    code: 'KF103',
    severity: 'error',
    text: (got: string) => `not a Kleinflow document (format is ${got}, expected "kleinflow")`,
  },
  futureVersion: {
    code: 'KF104',
    severity: 'error',
    text: (v: number, max: number) =>
      `document version ${v} is newer than this Kleinflow understands (${max})`,
  },
  tooManyNodes: {
    code: 'KF105',
    severity: 'error',
    text: (n: number, max: number) => `document has ${n} nodes; the limit is ${max}`,
  },
  duplicateNodeId: {
    code: 'KF201',
    severity: 'error',
    text: (id: string, first: string) => `duplicate node id "${id}": ${first} already has it`,
  },
  duplicateEdgeId: { code: 'KF202', severity: 'error', text: (id: string) => `duplicate edge id "${id}"` },
  unknownNodeType: {
    code: 'KF203',
    severity: 'error',
    text: (type: string) => `unknown node type "${type}" (kept as a placeholder; its data is preserved)`,
  },
  danglingEdge: {
    code: 'KF204',
    severity: 'error',
    text: (end: string, node: string) => `edge ${end} names node "${node}", which does not exist`,
  },
  unknownPort: {
    code: 'KF205',
    severity: 'error',
    text: (end: string, port: string, node: string) =>
      `edge ${end} names port "${port}", which node "${node}" does not have`,
  },
  typeMismatch: {
    code: 'KF206',
    severity: 'error',
    text: (from: string, to: string) => `cannot connect a ${from} output to a ${to} input`,
  },
  multipleEdges: {
    code: 'KF207',
    severity: 'error',
    text: (port: string) => `input "${port}" takes one edge but has several`,
  },
  cycle: { code: 'KF208', severity: 'error', text: (ids: string) => `cycle through nodes ${ids}` },
  selfEdge: { code: 'KF209', severity: 'error', text: (node: string) => `node "${node}" is wired to itself` },
  noRender: {
    code: 'KF210',
    severity: 'warning',
    text: () => 'the graph has no render node: nothing is drawn',
  },
  manyRenders: {
    code: 'KF211',
    severity: 'warning',
    text: (used: string) => `several render nodes; "${used}" (first by id) is drawn`,
  },
  badParam: {
    code: 'KF301',
    severity: 'error',
    text: (name: string, detail: string) => `${name}: ${detail}`,
  },
  upstreamMissing: {
    code: 'KF302',
    severity: 'error',
    text: (port: string, node: string) => `input "${port}" has no value because ${node} failed`,
  },
  degenerate: { code: 'KF303', severity: 'error', text: (detail: string) => detail },
  notATiling: { code: 'KF304', severity: 'warning', text: (detail: string) => detail },
  nodeThrew: {
    code: 'KF305',
    severity: 'error',
    text: (detail: string) => `internal error while evaluating: ${detail}`,
  },
  nonFinite: {
    code: 'KF306',
    severity: 'error',
    text: (port: string) => `output "${port}" is not a finite number (NaN or ∞)`,
  },
  noIntersection: {
    code: 'KF307',
    severity: 'warning',
    text: (detail: string) => `${detail}: the intersection outputs have no value`,
  },
  noPortValue: {
    code: 'KF308',
    severity: 'info',
    text: (port: string, node: string, output: string) =>
      `input "${port}" gets no value: ${node} has no "${output}" output in its current set-up`,
  },
  nodeVersion: { code: 'KF309', severity: 'error', text: (detail: string) => detail },
  pictureTooBig: {
    code: 'KF310',
    severity: 'warning',
    text: (what: string, limit: string) =>
      `the picture is too big (${what}; the limit is ${limit}): choose a smaller one; the built-in picture is shown instead`,
  },
  badPicture: {
    code: 'KF311',
    severity: 'warning',
    text: (detail: string) => `not a usable picture: ${detail}; the built-in picture is shown instead`,
  },
  tooManySeeds: {
    code: 'KF312',
    severity: 'warning',
    text: (n: number, max: number) => `${n} seeds are wired; only the first ${max} are drawn`,
  },
  inputMuted: {
    code: 'KF313',
    severity: 'info',
    text: (port: string, node: string) =>
      `input "${port}" is muted: ${node} is muted (or fed by a muted node) and passes nothing on`,
  },
  outsideMaskitSlice: {
    code: 'KF325',
    severity: 'info',
    text: (mu: string) =>
      `μ = ${mu} lies below the Maskit slice's boundary: that group is not discrete and free, and a Maskit group node given it draws no true limit set`,
  },
  groupPortMissing: {
    code: 'KF326',
    severity: 'error',
    text: (port: string, inner: string) =>
      `the group's port "${port}" names inner node "${inner}", which is not in the group: the port is not wired`,
  },
  formula: {
    code: 'KF327',
    severity: 'error',
    text: (message: string, at: string) => `formula, ${at}: ${message}`,
  },
  formulaSlope: {
    code: 'KF330',
    severity: 'warning',
    text: (slope: string, divisor: string) =>
      `the formula is not a distance bound: its slope reaches ${slope} (sampled in the bounding ball, where a distance's is at most 1), so the tracer divides it by ${divisor}; thin parts may still be missed — a formula that is a true distance draws faster and safer`,
  },
  formulaUndefined: {
    code: 'KF331',
    severity: 'warning',
    text: (at: string) =>
      `the formula is not a number at some points of the bounding ball, e.g. ${at} from the centre: the tracer cannot tell how far the surface is there and draws those points as surface`,
  },
  outsideSphairahedronSpace: { code: 'KF335', severity: 'warning', text: (detail: string) => detail },
  // Quaternion Kleinian groups (docs/math-3d.md "Quaternion Kleinian groups").
  quaternionSingular: {
    code: 'KF340',
    severity: 'error',
    text: (name: string, detail: string) => `generator ${name} is singular: ${detail}`,
  },
  quaternionNotSp: {
    code: 'KF341',
    severity: 'error',
    text: (name: string, detail: string) =>
      `generator ${name} is not a Möbius transformation of space (not in Sp^K(1,1)): ${detail}`,
  },
  drawnInstead: { code: 'KF315', severity: 'info', text: (detail: string) => detail },
  cameraInside: {
    code: 'KF316',
    severity: 'warning',
    text: (what: string, why: string) => `the camera is inside ${what}: ${why}`,
  },
  seedOutsideDomain: {
    code: 'KF314',
    severity: 'warning',
    text: (seed: string, element: string) =>
      `seed "${seed}" is not in the fundamental domain: the region of element "${element}" holds part of it, so its images overlap (move the seed out of that region)`,
  },
  cameraUnavailable: {
    code: 'KF320',
    severity: 'warning',
    text: (why: string) => `the camera could not start (${why}): the fallback picture is drawn instead`,
  },
  cameraOff: {
    code: 'KF321',
    severity: 'info',
    text: () =>
      'the camera is off: press “Start camera” (in the render or here; the browser asks once). Until then the fallback picture is drawn',
  },
  videoMissing: {
    code: 'KF322',
    severity: 'info',
    text: (name: string) =>
      `choose the video file${name ? ` “${name}”` : ''} in the inspector (a large video is not kept in the document): until then the fallback picture is drawn`,
  },
  videoUnplayable: {
    code: 'KF323',
    severity: 'warning',
    text: (why: string) => `the video could not be played (${why}): the fallback picture is drawn instead`,
  },
  liveFallback: {
    code: 'KF324',
    severity: 'info',
    text: (what: string) =>
      `${what} is a live source, only in the browser: the fallback picture is drawn here`,
  },
  tooManyElements: {
    code: 'KF401',
    severity: 'error',
    text: (n: number, max: number) =>
      `the scene has ${n} elements; the limit is ${max} (the extra ones are ignored)`,
  },
  clamped: { code: 'KF402', severity: 'warning', text: (what: string) => what },
  shaderCompile: {
    code: 'KF403',
    severity: 'error',
    text: (detail: string) => `shader failed to compile: ${detail}`,
  },
  uniformBudget: {
    code: 'KF404',
    severity: 'warning',
    text: (rows: number, max: number) =>
      `the scene needs ${rows} uniform vectors, more than the ${max} every WebGL2 GPU offers: its values are built into the shader instead (editing them recompiles it)`,
  },
  gpuRange: {
    code: 'KF405',
    severity: 'warning',
    text: (value: number, max: number, what = 'this element') =>
      `a value of ${value} is beyond what the GPU computes with (±${max.toExponential()}): the shader overflows to ∞ there, so ${what} does not draw as the CPU preview does`,
  },
  keptSides: { code: 'KF406', severity: 'warning', text: (detail: string) => detail },
  mirrorAngle: { code: 'KF407', severity: 'warning', text: (detail: string) => detail },
  importProblem: { code: 'KF501', severity: 'error', text: (detail: string) => detail },
  importNote: { code: 'KF502', severity: 'warning', text: (detail: string) => detail },
  pngRefused: {
    code: 'KF504',
    severity: 'error',
    text: (why: string) => `the PNG is refused: ${why}`,
  },
  migrated: {
    code: 'KF503',
    severity: 'info',
    text: (from: number, to: number) => `document upgraded from format version ${from} to ${to}`,
  },
});

export type DiagnosticKey = keyof typeof DIAGNOSTICS;

type Args<K extends DiagnosticKey> = Parameters<(typeof DIAGNOSTICS)[K]['text']>;

/** Builds a diagnostic from the table: `diag('cycle', { nodeId }, 'a → b → a')`. */
export function diag<K extends DiagnosticKey>(
  key: K,
  where: { path?: string; nodeId?: string; port?: string },
  ...args: Args<K>
): Diagnostic {
  const entry = DIAGNOSTICS[key];
  const text = entry.text as (...a: Args<K>) => string;
  return { code: entry.code, severity: entry.severity, message: text(...args), ...where };
}

export const hasErrors = (ds: readonly Diagnostic[]): boolean => ds.some((d) => d.severity === 'error');
