/** Bounds shared by the validator, evaluator and compiler (one home for each limit). */
export const LIMITS = {
  maxElements: 256,
  maxIterations: 10_000,
  maxSamples: 256,
  /** Deepest Cayley graph the render node draws (docs/math.md "Cayley graph and depth-first limit set"). */
  maxCayleyDepth: 12,
  maxNodes: 5_000,
  /**
   * Deepest nesting of objects and arrays a document may have (the document itself is level 0).
   * Real documents need about 8; JSON.stringify and structuredClone overflow at a few thousand.
   */
  maxJsonDepth: 64,
  defaultMaxIterations: 100,
  /**
   * vec4 uniform rows a generated fragment shader may declare: WebGL2 guarantees 224
   * (MAX_FRAGMENT_UNIFORM_VECTORS); 16 stay free for what ANGLE and drivers add internally.
   */
  maxUniformVectors: 208,
  /**
   * Largest magnitude of a scene number the GPU computes with safely: the shader squares
   * coordinates and radii in float32 (max ≈ 3.4e38), so |v| must stay below √3.4e38 ≈ 1.8e19.
   */
  gpuMaxMagnitude: 1e19,
  /** Largest width or height of an exported image (CLI render, PNG export), in pixels. */
  maxImageSide: 16_384,
  /** Share links: the longest `#g=` fragment accepted (characters of base64url). */
  shareFragmentMaxChars: 512 * 1024,
  /** Share links: the most bytes a fragment may inflate to (stops a zip bomb early). */
  shareInflatedMaxBytes: 4 * 1024 * 1024,
  /** Longest picture data: URL an image node keeps (the document carries it inline). */
  maxImageDataUrlChars: 4 * 1024 * 1024,
  /**
   * Longest video data: URL an image node keeps inline (about a 1.5 MB file: a short loop). A
   * bigger video is kept by name only and chosen again after reopening (README "Live sources").
   */
  maxVideoDataUrlChars: 2 * 1024 * 1024,
  /** Largest width or height of a picture used as a texture (every WebGL2 GPU has 4096). */
  maxPictureSide: 4096,
  /** Orbit seeds a tile may have (each one is tested at every step of every sample). */
  maxSeeds: 16,
  /** 3D render: sphere-tracing steps per ray (each runs the whole IIS), and the default. */
  maxMarchSteps: 2_000,
  defaultMarchSteps: 200,
  /** 3D render: the default IIS budget per distance estimate (each march step runs it). */
  defaultMaxIterations3d: 30,
} as const;

/**
 * The first number with |v| > max inside `value` (arrays and objects, iteratively: no recursion
 * limit), or undefined: the scene values the GPU would overflow on (LIMITS.gpuMaxMagnitude).
 */
export function firstBeyond(value: unknown, max: number): number | undefined {
  const stack: unknown[] = [value];
  while (stack.length > 0) {
    const v = stack.pop();
    if (typeof v === 'number') {
      if (Math.abs(v) > max) return v;
    } else if (Array.isArray(v)) stack.push(...v);
    else if (v !== null && typeof v === 'object') stack.push(...Object.values(v));
  }
  return undefined;
}
