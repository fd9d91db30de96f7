/**
 * How an unconnected input's value is written in a document's `params`, per port type, and how
 * it becomes the runtime value (PortValueMap). Colours are "#rrggbb" on disk, [r, g, b] at run time.
 */
import { z } from 'zod';
import type { PortType } from './ports.ts';
import type { Color } from './values.ts';

const finite = z.number().finite();
const vec2 = z.tuple([finite, finite]);

export const hexColor = z
  .string()
  .regex(/^#[0-9a-fA-F]{6}$/, 'expected a colour like "#ff8800"')
  .transform(
    (s): Color => [1, 3, 5].map((i) => Number.parseInt(s.slice(i, i + 2), 16) / 255) as unknown as Color,
  );

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
};

/** Runtime value → the JSON that PORT_VALUE_SCHEMA reads back (the inverse of parsing). */
export function portValueToJson(type: PortType, value: unknown): unknown {
  return type === 'color' ? toHex(value as Color) : value;
}
