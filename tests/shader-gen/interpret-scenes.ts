/** Scene builders shared by the interpreter tests. */
import type { InversionElement, ReflectionElement, SceneElement } from '../../nodes/core/scene.ts';
import type { Vec2 } from '../../nodes/core/values.ts';

export const inv = (c: Vec2, r: number, nodeId = 'i'): InversionElement => ({
  kind: 'inversion',
  nodeId,
  c,
  r,
});
export const refl = (q: Vec2, n: Vec2, nodeId = 'r'): ReflectionElement => ({
  kind: 'reflection',
  nodeId,
  q,
  n,
});
export const scene = (elements: readonly SceneElement[], maxIterations = 100) => ({
  elements,
  maxIterations,
});

/** The four mirrors of the rectangle [0, a] × [0, b], kept sides facing in (the *2222 kaleidoscope). */
export const rectangle = (a: number, b: number): ReflectionElement[] => [
  refl([0, 0], [1, 0]),
  refl([a, 0], [-1, 0]),
  refl([0, 0], [0, 1]),
  refl([0, b], [0, -1]),
];
