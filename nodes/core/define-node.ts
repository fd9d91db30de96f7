/**
 * defineNode: the one declaration of a node type — ports, params, CPU evaluation, UI metadata,
 * migrations, overlay and drag handles. Adding a node type = one file + one line in registry.ts.
 */
import type { Diagnostic } from './diagnostics.ts';
import type { HandleItem, OverlayShape } from './overlay.ts';
import type { PortInputMap, PortValueMap } from './port-values.ts';
import type { ManyPortType, PortType } from './ports.ts';
import type { Scene } from './scene.ts';
import type { Handle3dItem, Overlay3dShape, Scene3d, Vec3 } from './scene-3d.ts';
import type { Color, Vec2 } from './values.ts';

export interface InputSpec {
  readonly type: PortType;
  readonly label?: string;
  readonly doc?: string;
  /** Value of the input while unconnected, in document (JSON) form. Absent for element/tile. */
  readonly default?: unknown;
  /** UI and validation hints for numbers: sliders when both bounds are set. */
  readonly min?: number;
  readonly max?: number;
  readonly step?: number;
  readonly integer?: boolean;
  /** Inputs that only make sense wired (element, tile) are not editable inline. */
  readonly optional?: boolean;
  /** Shown only while this condition holds (a wired input is always shown). See field-visibility.ts. */
  readonly when?: FieldCondition;
  /** Rarely changed: the node shows it under its collapsible "More" section (always, or while the condition holds). */
  readonly more?: true | FieldCondition;
}

/**
 * "This field matters only while param `param` (an enum or a toggle) has one of the values `is`."
 * Hiding a field never changes the document: its value is kept and still evaluated.
 */
export interface FieldCondition {
  readonly param: string;
  readonly is: readonly (string | boolean)[];
}

export interface OutputSpec {
  readonly type: PortType;
  readonly label?: string;
  readonly doc?: string;
  /**
   * The node may work yet leave this output empty (no intersection; no disk unless hyperbolic):
   * inputs wired to it then say why. Outputs without it are always set when the node works.
   */
  readonly optional?: true;
}

/** What every param declares besides its kind: label, doc, and when the editor shows it. */
interface ParamUi {
  readonly label?: string;
  readonly doc?: string;
  /** Shown only while this condition holds. See field-visibility.ts. */
  readonly when?: FieldCondition;
  /** Rarely changed: the node shows it under its collapsible "More" section (always, or while the condition holds). */
  readonly more?: true | FieldCondition;
}

/** A parameter that cannot be wired: an enum, toggle, bounded integer, text or colour. */
export type ParamSpec = ParamUi &
  (
    | { readonly kind: 'boolean'; readonly default: boolean }
    | { readonly kind: 'enum'; readonly default: string; readonly options: readonly string[] }
    | {
        readonly kind: 'number';
        readonly default: number;
        readonly min?: number;
        readonly max?: number;
        readonly step?: number;
        readonly integer?: boolean;
      }
    | { readonly kind: 'color'; readonly default: string }
    | {
        readonly kind: 'string';
        readonly default: string;
        /** Longest text accepted (default 10 000 characters; a picture's data: URL needs more). */
        readonly maxLength?: number;
      }
  );

/** The erased shapes of a definition's declarations (what the registry and the editor read). */
export type InputSpecs = Readonly<Record<string, InputSpec>>;
export type OutputSpecs = Readonly<Record<string, OutputSpec>>;
export type ParamSpecs = Readonly<Record<string, ParamSpec>>;

/**
 * What evaluate receives on input `S`: a many-input (element, seed) the flat array of all its
 * wires' values (empty when unwired); an input with a default always a value; an optional input,
 * or one without a default, possibly nothing (unwired, or its source left that output empty).
 */
export type InputValue<S extends InputSpec> = S['type'] extends ManyPortType
  ? PortInputMap[S['type']]
  : S extends { readonly optional: true }
    ? PortValueMap[S['type']] | undefined
    : S extends { readonly default: unknown }
      ? PortValueMap[S['type']]
      : PortValueMap[S['type']] | undefined;

/** A param's runtime value by its kind: an enum is the union of its options, a colour [r, g, b]. */
export type ParamValue<S extends ParamSpec> = S extends { readonly kind: 'enum'; readonly options: infer O }
  ? O extends readonly (infer V)[]
    ? V
    : string
  : { boolean: boolean; number: number; color: Color; string: string; enum: string }[S['kind']];

export type InputValuesOf<I extends InputSpecs> = { readonly [K in keyof I]: InputValue<I[K]> };
export type ParamValuesOf<P extends ParamSpecs> = { readonly [K in keyof P]: ParamValue<P[K]> };

/** Output names a node may leave empty although it worked (declared `optional: true`). */
type OptionalOutputs<O extends OutputSpecs> = {
  [K in keyof O]: O[K] extends { readonly optional: true } ? K : never;
}[keyof O];
/** The outputs a working node returns: every declared output, the optional ones possibly absent. */
export type OutputValuesOf<O extends OutputSpecs> = {
  readonly [K in Exclude<keyof O, OptionalOutputs<O>>]: PortValueMap[O[K]['type']];
} & { readonly [K in OptionalOutputs<O>]?: PortValueMap[O[K]['type']] };

/** Erased forms, used where definitions of every type meet (registry, evaluator, editor). */
export type InputValues = Readonly<Record<string, unknown>>;
export type ParamValues = Readonly<Record<string, unknown>>;
export type OutputValues = Readonly<Record<string, unknown>>;

export interface EvalContext<In = InputValues, Pa = ParamValues> {
  readonly nodeId: string;
  /** Resolved inputs (wired or inline). Element inputs are always arrays (possibly empty). */
  readonly inputs: In;
  /** Non-wirable params, validated against their specs and filled with defaults. */
  readonly params: Pa;
  /** Seconds since the animation started (0 when not animating). */
  readonly time: number;
}

/** What the render node adds to the Scene (the single output of the graph). */
export type RenderSettings = Pick<
  Scene,
  'elements' | 'tile' | 'maxIterations' | 'samples' | 'clip' | 'figures'
>;

/** What the 3D render node adds to the Scene3d (the evaluator adds overlays, handles and its id). */
export type Render3dSettings = Omit<Scene3d, 'kind' | 'renderNodeId' | 'overlays' | 'handles'>;

export interface EvalOutcome<Out = OutputValues> {
  /** Output values by port name; a missing output has no value (dependants report why). */
  readonly outputs?: Out;
  readonly diagnostics?: readonly Diagnostic[];
  /** A short read-out shown on the node, e.g. "elliptic, rotation 120°". */
  readonly readout?: string;
  /** Only the render node sets this. */
  readonly render?: RenderSettings;
  /** Only the render-3d node sets this. */
  readonly render3d?: Render3dSettings;
}

/** A drag's result: new document-form values of some of the node's inputs and params. */
export type DragPatch<Name extends PropertyKey = string> = { readonly [K in Name]?: unknown };

/** What every definition states besides its ports, params and callbacks. */
interface NodeMeta {
  /** Stable kebab-case id stored in documents. */
  readonly type: string;
  readonly version: number;
  readonly label: string;
  readonly category:
    | 'Values'
    | 'Geometry'
    | 'Construction'
    | 'Generators'
    | 'Kaleidoscopes'
    | 'Colour'
    | 'Animation'
    | 'Output'
    /** Nodes of space: points, spheres, planes, 3D generators and seeds, the 3D render. */
    | '3D';
  readonly color: string;
  /** One line shown in the palette, inspector and README. */
  readonly doc: string;
  /**
   * migrations[v] turns the params of a version-v node into version v+1 params. Every version
   * below `version` needs one.
   */
  readonly migrations?: Readonly<
    Record<number, (params: Record<string, unknown>) => Record<string, unknown>>
  >;
}

/**
 * One node type as written in its file: the port and param declarations type everything else, so
 * `inputs.radius` is a number, `params.mode` the union of its options, a misspelt name does not
 * compile, and the outputs evaluate returns must match the declared ones.
 */
export interface NodeDefinition<I extends InputSpecs, O extends OutputSpecs, P extends ParamSpecs>
  extends NodeMeta {
  readonly inputs: I;
  readonly outputs: O;
  readonly params: P;
  readonly evaluate: (
    ctx: EvalContext<InputValuesOf<I>, ParamValuesOf<P>>,
  ) => EvalOutcome<OutputValuesOf<NoInfer<O>>>;
  /** What the overlay draws from the evaluated values (in the node's colour); only after success. */
  readonly overlay?: (
    ctx: EvalContext<InputValuesOf<I>, ParamValuesOf<P>>,
    outputs: OutputValuesOf<NoInfer<O>>,
  ) => readonly OverlayShape[];
  /**
   * Draggable handles at their current positions. Also asked of a node that failed (its outputs
   * are then missing), so the user can drag it back into shape.
   */
  readonly handles?: (
    ctx: EvalContext<InputValuesOf<I>, ParamValuesOf<P>>,
    outputs: Partial<OutputValuesOf<NoInfer<O>>>,
  ) => readonly Omit<HandleItem, 'nodeId'>[];
  /**
   * Maps a drag of `handle` to world point `to` onto new values (document form) of this node's
   * unconnected inputs / params. When a key names a connected point input, the editor drags the
   * upstream node that produces that point instead (its first handle), so geometry stays wired.
   */
  readonly drag?: (
    handle: string,
    to: Vec2,
    ctx: EvalContext<InputValuesOf<I>, ParamValuesOf<P>>,
  ) => DragPatch<keyof I | keyof P>;
  /** The 3D view's wireframe of the node (after success), like `overlay` for the plane. */
  readonly overlay3d?: (
    ctx: EvalContext<InputValuesOf<I>, ParamValuesOf<P>>,
    outputs: OutputValuesOf<NoInfer<O>>,
  ) => readonly Overlay3dShape[];
  /** Draggable points in space; like `handles`, also asked of a node that failed. */
  readonly handles3d?: (
    ctx: EvalContext<InputValuesOf<I>, ParamValuesOf<P>>,
    outputs: Partial<OutputValuesOf<NoInfer<O>>>,
  ) => readonly Omit<Handle3dItem, 'nodeId'>[];
  /**
   * A drag of a 3D handle to `to` → new document-form values of this node's inputs / params; a key
   * naming a wired point3 input moves the upstream node instead (nodes/graph/drag-patches-3d.ts).
   */
  readonly drag3d?: (
    handle: string,
    to: Vec3,
    ctx: EvalContext<InputValuesOf<I>, ParamValuesOf<P>>,
  ) => DragPatch<keyof I | keyof P>;
}

/**
 * A node type with its own types erased: what the registry, the evaluator and the editor hold.
 * The callbacks are declared as methods on purpose: method parameters compare bivariantly, which
 * is what lets every NodeDefinition<I, O, P> be stored here without a cast. It is sound because
 * the evaluator builds each ctx from the very specs that typed it (graph/params.ts, evaluate.ts).
 */
export interface NodeDef extends NodeMeta {
  readonly inputs: InputSpecs;
  readonly outputs: OutputSpecs;
  readonly params: ParamSpecs;
  evaluate(ctx: EvalContext): EvalOutcome;
  overlay?(ctx: EvalContext, outputs: OutputValues): readonly OverlayShape[];
  handles?(ctx: EvalContext, outputs: OutputValues): readonly Omit<HandleItem, 'nodeId'>[];
  drag?(handle: string, to: Vec2, ctx: EvalContext): DragPatch;
  overlay3d?(ctx: EvalContext, outputs: OutputValues): readonly Overlay3dShape[];
  handles3d?(ctx: EvalContext, outputs: OutputValues): readonly Omit<Handle3dItem, 'nodeId'>[];
  drag3d?(handle: string, to: Vec3, ctx: EvalContext): DragPatch;
}

/**
 * Declares a node type: returns the definition unchanged after checking its id. `const` keeps the
 * declarations' literal types (port types, enum options) from which the callbacks are typed.
 */
export function defineNode<
  const I extends InputSpecs,
  const O extends OutputSpecs,
  const P extends ParamSpecs,
>(def: NodeDefinition<I, O, P>): NodeDefinition<I, O, P> {
  if (!/^[a-z][a-z0-9]*(-[a-z0-9]+)*$/.test(def.type))
    throw new Error(`node type id "${def.type}" is not kebab-case`);
  return def;
}
