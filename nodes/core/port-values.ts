/**
 * How an unconnected input's value is written in a document's `params`, per port type, and how
 * it becomes the runtime value (PortValueMap). Colours are "#rrggbb" on disk, [r, g, b] at run time.
 */
import { z } from 'zod';
import { normalize3 } from '../geometry/space/vec3.ts';
import type { LimitSet3d } from './limit-set-3d.ts';
import type { ManyPortType, PortType } from './ports.ts';
import type { NodeElement3d, Plane, Seed3d, Sphere, Vec3 } from './scene-3d.ts';
import type { SceneElement } from './scene-elements.ts';
import type { SeedSpec, TileSpec } from './tile-spec.ts';
import type { Circle, Color, ImageRef, Line, Vec2 } from './values.ts';

/** What a port of each type carries at evaluation time. */
export interface PortValueMap {
  number: number;
  point: Vec2;
  line: Line;
  circle: Circle;
  element: readonly SceneElement[];
  tile: TileSpec;
  color: Color;
  image: ImageRef;
  seed: SeedSpec;
  point3: Vec3;
  sphere: Sphere;
  /** Its normal is a unit vector (the inline schema and the plane node normalise it). */
  plane: Plane;
  element3: readonly NodeElement3d[];
  seed3: Seed3d;
  limit3: LimitSet3d;
}

/** One value of a many-type's list (an element output already carries a list). */
type Item<V> = V extends readonly (infer E)[] ? E : V;

/** What an input of each type receives: many-inputs get every wire's values in one flat array. */
export type PortInputMap = {
  [T in PortType]: T extends ManyPortType ? readonly Item<PortValueMap[T]>[] : PortValueMap[T];
};

const finite = z.number().finite();
const vec2 = z.tuple([finite, finite]);
const vec3 = z.tuple([finite, finite, finite]);
/** A plane as written: any non-zero normal, normalised on reading (the runtime Plane's is unit). */
const plane = z
  .object({ point: vec3, normal: vec3 })
  .refine((p) => Math.hypot(...p.normal) > 0, 'the plane normal must not be zero')
  .transform((p): Plane => ({ point: p.point, normal: normalize3(p.normal) }));

export const hexColor = z
  .string()
  .regex(/^#[0-9a-fA-F]{6}$/, 'expected a colour like "#ff8800"')
  .transform((s): Color => {
    const [r, g, b] = [1, 3, 5].map((i) => Number.parseInt(s.slice(i, i + 2), 16) / 255);
    return [r, g, b];
  });

/** Color → "#rrggbb" (components clamped to [0, 1]). */
export function toHex(c: Color): string {
  return `#${c
    .map((v) =>
      Math.round(Math.min(1, Math.max(0, v)) * 255)
        .toString(16)
        .padStart(2, '0'),
    )
    .join('')}`;
}

/** Schemas of editable (unconnected) input values; `null` = the type has no inline value. */
export const PORT_VALUE_SCHEMA: Readonly<Record<PortType, z.ZodType | null>> = {
  number: finite,
  point: vec2,
  line: z.object({ a: vec2, b: vec2 }),
  circle: z.object({ c: vec2, r: finite }),
  element: null,
  tile: null,
  color: hexColor,
  image: z.object({ src: z.string(), width: finite, height: finite }),
  seed: null,
  point3: vec3,
  sphere: z.object({ center: vec3, radius: finite }),
  plane,
  element3: null,
  seed3: null,
  limit3: null,
};

/** Runtime value → the JSON that PORT_VALUE_SCHEMA reads back (the inverse of parsing). */
export function portValueToJson(type: PortType, value: unknown): unknown {
  return type === 'color' ? toHex(value as Color) : value;
}
