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
import type { ImageRef } from '../nodes/core/values.ts';
import { farDisk, limitReach } from './far-disk.ts';

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

/** A picture as a baked program sees it: its size (the pixels are a texture, never literals). */
const pictureShape = (key: string, value: unknown) =>
  key === 'image' && value && typeof value === 'object' && 'src' in value
    ? { width: (value as unknown as ImageRef).width, height: (value as unknown as ImageRef).height }
    : value;

/** Every value a baked program writes as a literal, in a fixed order (elements without node ids). */
function bakedValues(scene: Scene): string {
  const elements = scene.elements.map(({ nodeId: _, ...rest }) => rest);
  const { coloring, limitColor, background, edgeWidth, edgeColor, fill, inner, seedFade } = scene.tile;
  const seeds = (scene.tile.seeds ?? []).map(({ nodeId: _, ...rest }) => rest);
  return JSON.stringify(
    [
      elements,
      coloring,
      limitColor,
      background,
      edgeWidth,
      edgeColor,
      scene.clip,
      fill,
      inner,
      seeds,
      seedFade,
    ],
    pictureShape,
  );
}

/**
 * The tile options that change the code: fill, seeds (kinds in order; with seedsOnly), inner
 * circle, glow and the limit-set estimate, the far-chart edge distance, and which sampler each picture uses (pictures with
 * the same src share one).
 */
function tileOptions(scene: Scene): string[] {
  const { tile } = scene;
  const parts: string[] = [];
  if (tile.fill) parts.push('fill:on');
  const seeds = tile.seeds ?? [];
  if (seeds.length > 0)
    parts.push(`seeds:${seeds.map((s) => s.kind).join(',')}${tile.seedsOnly ? ':only' : ''}`);
  if (seeds.length > 0 && tile.seedFade) parts.push('seedFade:on');
  if (tile.inner) parts.push('inner:on');
  if (tile.coloring.mode === 'limit-set') {
    if (tile.coloring.glow > 0) parts.push('glow:on');
    if (limitReach(scene.elements) !== null) parts.push('reach:on');
  }
  if ((tile.edgeWidth > 0 || tile.coloring.mode === 'limit-set') && farDisk(scene.elements))
    parts.push('far:on');
  const srcs: string[] = [];
  if (tile.coloring.mode === 'image') srcs.push(tile.coloring.image.src);
  for (const s of seeds) if (s.kind === 'image') srcs.push(s.image.src);
  if (srcs.length > 0) parts.push(`pictures:${srcs.map((src) => srcs.indexOf(src)).join(',')}`);
  return parts;
}

export function structureKey(scene: Scene, options: StructureKeyOptions): string {
  const parts = [
    options.variant,
    options.baked ? 'baked' : 'uniform',
    `elements:${kindRuns(scene)}`,
    `colouring:${scene.tile.coloring.mode}`,
    `edges:${scene.tile.edgeWidth > 0 ? 'on' : 'off'}`,
    `clip:${scene.clip ? 'on' : 'off'}`,
    ...tileOptions(scene),
  ];
  if (options.baked)
    parts.push(`maxIterations:${scene.maxIterations}`, `values:${fnv1a64(bakedValues(scene))}`);
  return parts.join('|');
}
