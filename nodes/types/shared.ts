/** Small helpers shared by node type files (outcomes, common port and param specs). */
import type { EvalOutcome, InputSpec, ParamSpec } from '../core/define-node.ts';
import { diag } from '../core/diagnostics.ts';

/** A node error for a degenerate or invalid set-up; the node has no outputs (so it fits every node). */
export const fail = (reason: string, readout?: string): EvalOutcome<never> => ({
  diagnostics: [diag('degenerate', {}, reason)],
  ...(readout ? { readout } : {}),
});

/** The overlay toggle every geometric node has. */
export const VISIBLE = {
  kind: 'boolean',
  default: true,
  label: 'show',
  doc: 'draw it over the render',
} as const satisfies ParamSpec;

export const pointInput = (label: string, x: number, y: number) =>
  ({ type: 'point', label, default: [x, y] }) as const satisfies InputSpec;
export const elementInput = (label: string) =>
  ({ type: 'element', label, optional: true }) as const satisfies InputSpec;

/** Formats a number for read-outs: up to 4 significant decimals, no trailing zeros. */
export const fmt = (v: number): string => (Number.isInteger(v) ? String(v) : String(Number(v.toFixed(4))));
export const degrees = (radians: number): string => `${fmt((radians * 180) / Math.PI)}°`;
