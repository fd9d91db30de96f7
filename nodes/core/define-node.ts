/**
 * defineNode: the one declaration of a node type — ports, params, CPU evaluation, UI metadata,
 * migrations, overlay and drag handles. Adding a node type = one file + one line in registry.ts.
 */
import type { Diagnostic } from './diagnostics.ts';
import type { PortType } from './ports.ts';
import type { HandleItem, OverlayShape, Scene } from './scene.ts';
import type { PortValueMap, Vec2 } from './values.ts';

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

export type InputValues = Readonly<Record<string, PortValueMap[PortType] | undefined>>;
export type ParamValues = Readonly<Record<string, unknown>>;

export interface EvalContext {
  readonly nodeId: string;
  /** Resolved inputs (wired or inline). Element inputs are always arrays (possibly empty). */
  readonly inputs: InputValues;
  /** Non-wirable params, validated against their specs and filled with defaults. */
  readonly params: ParamValues;
  /** Seconds since the animation started (0 when not animating). */
  readonly time: number;
}

/** What the render node adds to the Scene (the single output of the graph). */
export type RenderSettings = Pick<Scene, 'elements' | 'tile' | 'maxIterations' | 'samples' | 'clip'>;

export interface EvalOutcome {
  /** Output values by port name; a missing output has no value (dependants report why). */
  readonly outputs?: Readonly<Record<string, unknown>>;
  readonly diagnostics?: readonly Diagnostic[];
  /** A short read-out shown on the node, e.g. "elliptic, rotation 120°". */
  readonly readout?: string;
  /** Only the render node sets this. */
  readonly render?: RenderSettings;
}

export interface NodeDef {
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
    | 'Output';
  readonly color: string;
  /** One line shown in the palette, inspector and README. */
  readonly doc: string;
  readonly inputs: Readonly<Record<string, InputSpec>>;
  readonly outputs: Readonly<Record<string, OutputSpec>>;
  readonly params: Readonly<Record<string, ParamSpec>>;
  readonly evaluate: (ctx: EvalContext) => EvalOutcome;
  /**
   * migrations[v] turns the params of a version-v node into version v+1 params. Every version
   * below `version` needs one.
   */
  readonly migrations?: Readonly<
    Record<number, (params: Record<string, unknown>) => Record<string, unknown>>
  >;
  /** What the overlay draws from the evaluated values (in the node's colour). */
  readonly overlay?: (
    ctx: EvalContext,
    outputs: Readonly<Record<string, unknown>>,
  ) => readonly OverlayShape[];
  /** Draggable handles at their current positions. */
  readonly handles?: (
    ctx: EvalContext,
    outputs: Readonly<Record<string, unknown>>,
  ) => readonly Omit<HandleItem, 'nodeId'>[];
  /**
   * Maps a drag of `handle` to world point `to` onto new values (document form) of this node's
   * unconnected inputs / params. When a key names a connected point input, the editor drags the
   * upstream node that produces that point instead (its first handle), so geometry stays wired.
   */
  readonly drag?: (handle: string, to: Vec2, ctx: EvalContext) => Readonly<Record<string, unknown>>;
}

/** Declares a node type. Identity function with defaults filled in and the id checked. */
export function defineNode(def: NodeDef): NodeDef {
  if (!/^[a-z][a-z0-9]*(-[a-z0-9]+)*$/.test(def.type))
    throw new Error(`node type id "${def.type}" is not kebab-case`);
  return def;
}
