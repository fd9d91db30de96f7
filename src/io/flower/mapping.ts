/**
 * What mapping one Flower node gives (the shapes node-types.ts and orbit-seed.ts produce and
 * import.ts consumes). A module of its own so that the mappers and the table that lists them do
 * not import each other.
 */
import type { NodeRegistry } from '../../../nodes/core/registry.ts';
import type { FlowerNode } from './format.ts';

/** Where a Flower output socket's value comes from in Kleinflow. */
export type OutputSource = { readonly port: string } | { readonly passthroughInput: number } | null;

export interface MappedNode {
  readonly type: string;
  /** Id prefix (upper case, so mirrors' lower-case ids sort after every node they depend on). */
  readonly prefix: string;
  readonly params: Record<string, unknown>;
  /** Kleinflow input port per Flower input ordinal (null: that input has no twin). */
  readonly inputs: readonly (string | null)[];
  readonly outputs: readonly OutputSource[];
  /** Mirrors are wired into the render: circles first, then lines (Flower's test order). */
  readonly mirror?: 'circle' | 'line';
  /** Orbit seeds: their `seed` output is wired into the imported tile's `seeds`, in file order. */
  readonly seed?: boolean;
  /** The input that the import's shared Time node drives (animated nodes). */
  readonly timeInput?: string;
  /** Warnings about what did not carry over. */
  readonly notes: readonly string[];
}

/** No Kleinflow node: `skip` says why (a warning), or null when nothing is lost (values read elsewhere). */
export type Mapping = MappedNode | { readonly skip: string | null };

export interface MapContext {
  readonly registry: NodeRegistry;
  /** Flower input ordinals of this node that have an edge. */
  readonly wired: ReadonlySet<number>;
  /** Flower type names of the nodes this node's outputs feed. */
  readonly consumers: readonly string[];
}

/** Maps one Flower node of a given type. */
export type FlowerTypeMap = (node: FlowerNode, ctx: MapContext) => Mapping;
