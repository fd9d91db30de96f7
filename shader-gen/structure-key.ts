/**
 * structureKey: what changes the generated code, never the values a uniform carries. Two scenes
 * with the same key compile to the same program text (up to uniform values), so the runtime reuses
 * the linked program and only uploads uniforms; dragging a point never recompiles.
 *
 * In the key: the variant, uniform or baked, the element kinds in order, the colouring mode,
 * edges on/off, clip on/off. A baked program has every value in its text, so its key adds
 * maxIterations and a hash of all the baked values.
 */
import type { Scene } from '../nodes/core/scene.ts';

export interface StructureKeyOptions {
  readonly variant: 'color' | 'probe';
  readonly baked: boolean;
}

/** 64-bit FNV-1a of a string, as 16 hex digits (stable across runs and platforms). */
export function fnv1a64(text: string): string {
  let h = 0xcbf29ce484222325n;
  const prime = 0x100000001b3n;
  const mask = 0xffffffffffffffffn;
  for (let i = 0; i < text.length; i++) {
    h ^= BigInt(text.charCodeAt(i));
    h = (h * prime) & mask;
  }
  return h.toString(16).padStart(16, '0');
}

/** Element kinds in order, runs written once with a count: `reflection*2,inversion`. */
function kindRuns(scene: Pick<Scene, 'elements'>): string {
  const runs: string[] = [];
  let i = 0;
  while (i < scene.elements.length) {
    let j = i;
    while (j < scene.elements.length && scene.elements[j].kind === scene.elements[i].kind) j++;
    runs.push(j - i > 1 ? `${scene.elements[i].kind}*${j - i}` : scene.elements[i].kind);
    i = j;
  }
  return runs.join(',');
}

/** Every value a baked program writes as a literal, in a fixed order (elements without node ids). */
function bakedValues(scene: Scene): string {
  const elements = scene.elements.map(({ nodeId: _, ...rest }) => rest);
  const { coloring, limitColor, background, edgeWidth, edgeColor } = scene.tile;
  return JSON.stringify([elements, coloring, limitColor, background, edgeWidth, edgeColor, scene.clip]);
}

export function structureKey(scene: Scene, options: StructureKeyOptions): string {
  const parts = [
    options.variant,
    options.baked ? 'baked' : 'uniform',
    `elements:${kindRuns(scene)}`,
    `colouring:${scene.tile.coloring.mode}`,
    `edges:${scene.tile.edgeWidth > 0 ? 'on' : 'off'}`,
    `clip:${scene.clip ? 'on' : 'off'}`,
  ];
  if (options.baked)
    parts.push(`maxIterations:${scene.maxIterations}`, `values:${fnv1a64(bakedValues(scene))}`);
  return parts.join('|');
}
