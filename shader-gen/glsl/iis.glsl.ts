/**
 * The scene-specific GLSL: the IIS loop, the boundary distance over all elements and one sample's
 * colour, emitted as straight-line code per element (each block under its own `#line` marker).
 *
 *   runIis — the loop of interpret.ts runIis (docs/math.md, normative): at depth ≥ maxIter only ask
 *   whether some element holds p (→ not escaped); else step the first element that holds p and
 *   restart from the first; no element holds p → escaped. Every pass either returns or adds ≥ 1
 *   to depth, so after at most maxIter passes depth ≥ maxIter.
 */
import type { Measure, Scene, SceneElement } from '../../nodes/core/scene.ts';
import type { Circle } from '../../nodes/core/values.ts';
import { COLOUR_NAMES } from '../../nodes/formula/names.ts';
import type { ElementRecord } from '../elements/element-kind.ts';
import { elementRecord } from '../elements/index.ts';
import { farDisk, limitReach } from '../far-disk.ts';
import { type ColourSpace, shadeGlsl } from './colour.glsl.ts';
import { finiteFormulaFunction } from './formula.glsl.ts';
import { floatLiteral } from './literal.ts';
import type { SeedArg, SeedsGlsl } from './seeds.glsl.ts';
import { type GlslFunction, glslFunction } from './snippet.ts';
import type { SourceBuilder } from './source.ts';
import { ELEMENT_ARRAY, type SceneValues } from './values.ts';

/** Stands in for +∞ where the CPU starts a minimum at Infinity (GLSL ES has no literal for it). */
export const GLSL_FAR = '3.0e38';

interface PlacedElement {
  readonly element: SceneElement;
  readonly record: ElementRecord;
  /** GLSL expressions of its data vec4s (`u_el[i]` or literals). */
  readonly data: readonly string[];
  /** The same, joined as trailing call arguments. */
  readonly args: string;
}

/** The elements with their data placed in `u_el` (or baked), in graph order. */
export function placeElements(elements: readonly SceneElement[], v: SceneValues): PlacedElement[] {
  return elements.map((element) => {
    const record = elementRecord(element) as ElementRecord;
    const data = record.glsl.pack(element);
    if (data.length !== record.glsl.vec4s * 4)
      throw new Error(`${record.kind} packed ${data.length} numbers`);
    const rows = v.elementRows(data);
    return { element, record, data: rows, args: rows.join(', ') };
  });
}

/** Each kind's functions the loop calls (deduplicated by the assembler). */
export function elementFunctions(placed: readonly PlacedElement[], edges: boolean): GlslFunction[] {
  return placed.flatMap(({ record: { glsl } }) => [
    ...glsl.step.deps,
    glsl.inside,
    ...(edges ? [glsl.boundaryDistance] : []),
  ]);
}

const UNIFORM_ROW = new RegExp(`^${ELEMENT_ARRAY}\\[(\\d+)\\]$`);

/** The local `elN` that holds uniform row `u_el[N]` in runIis (null for a baked literal). */
const hoistedRow = (expr: string): string | null => {
  const m = UNIFORM_ROW.exec(expr);
  return m ? `el${m[1]}` : null;
};

/**
 * `bool runIis(inout vec2 p, inout float s, inout int depth)`: true when p escaped. The loop only
 * steps (each element's block: step it, and restart if it applied); once depth reaches maxIter
 * the blocks after the loop only ask whether some element holds p.
 *
 * Speed (SwiftShader, tests/bench/shader-ratio.ts): the uniform rows and maxIter are copied into
 * locals before the loop — read inside the loop, every pass reloaded them (2× slower) — and the
 * loop runs on depth alone, its increment counting each applied step (a twin adds only what a
 * step is worth beyond 1, see GlslStepBlock): every pass either returns or adds ≥ 1 to depth, so
 * there are at most maxIter passes without a second counter, and no block pays for an add.
 */
export function emitRunIis(
  out: SourceBuilder,
  placed: readonly PlacedElement[],
  maxIter: string,
  seedArgs: readonly SeedArg[] | null = null,
  trapCircle: string | null = null,
): void {
  const withSeeds = seedArgs !== null;
  const local = (expr: string) => hoistedRow(expr) ?? expr;
  const hoisted = placed.flatMap(({ data }) =>
    data.flatMap((expr) => {
      const name = hoistedRow(expr);
      return name ? [`  vec4 ${name} = ${expr};`] : [];
    }),
  );
  // Seed data in uniforms (names, not literals) are copied into locals like the element rows.
  const seedLocals = (seedArgs ?? []).map((a, k) => (/^\w+$/.test(a.expr) ? `seedArg${k}` : a.expr));
  (seedArgs ?? []).forEach((a, k) => {
    if (seedLocals[k] !== a.expr) hoisted.push(`  ${a.type} ${seedLocals[k]} = ${a.expr};`);
  });
  // An orbit trap (raster.ts's visit) is copied into a local like the seeds when it is a uniform.
  const trapLocal = trapCircle && /^\w+$/.test(trapCircle) ? 'trapCircle' : trapCircle;
  if (trapCircle && trapLocal !== trapCircle) hoisted.push(`  vec3 ${trapLocal} = ${trapCircle};`);
  // With seeds (interpret.ts runIis's `visit`): at the start of every pass, a point in a seed stops
  // the run, not escaped, with `seed` its index; an orbit trap sees the point first.
  const seedTest = (indent: string) => [
    ...(trapLocal ? [`${indent}trap = min(trap, orbitTrapDistance(p, ${trapLocal}));`] : []),
    ...(withSeeds
      ? [
          `${indent}seed = seedAt(${['p', ...seedLocals].join(', ')});`,
          `${indent}if (seed >= 0) return false;`,
        ]
      : []),
  ];
  const args = [
    'inout vec2 p',
    'inout float s',
    'inout int depth',
    ...(withSeeds ? ['inout int seed'] : []),
    ...(trapLocal ? ['inout float trap'] : []),
  ];
  const literalLimit = /^\d+$/.test(maxIter);
  out.push(
    `bool runIis(${args.join(', ')}) {`,
    ...hoisted,
    ...(literalLimit ? [] : [`  int maxIter = ${maxIter};`]),
    `  for (; depth < ${literalLimit ? maxIter : 'maxIter'}; ++depth) {`,
    ...seedTest('    '),
  );
  placed.forEach(({ record, data }, i) => {
    out.block(i + 1, [
      `    { // ${record.kind}`,
      ...data.map((expr, k) => `      vec4 d${k} = ${local(expr)};`),
      ...record.glsl.step.code.split('\n').map((line) => `      ${line}`),
      '    }',
    ]);
  });
  out.push('    return true;', '  }');
  out.push(...seedTest('  '));
  out.push('  // depth ≥ maxIter: escaped only if no element holds p.');
  placed.forEach(({ record, data }, i) => {
    out.block(i + 1, [`  if (${record.glsl.inside.name}(p, ${data.map(local).join(', ')})) return false;`]);
  });
  out.push('  return true;', '}');
}

/** `float sceneBoundaryDistance(vec2 p)`: min over elements of boundaryDistance (raster.ts). */
export function emitBoundaryDistance(out: SourceBuilder, placed: readonly PlacedElement[]): void {
  out.push('float sceneBoundaryDistance(vec2 p) {', `  float d = ${GLSL_FAR};`);
  placed.forEach(({ record, args }, i) => {
    out.block(i + 1, [`  d = min(d, ${record.glsl.boundaryDistance.name}(p, ${args}));`]);
  });
  out.push('  return d;', '}');
}

/**
 * Statements setting `bool clipped` for the world point `w`: trace.ts outsideClip, |w − c|² > r²
 * (false when the scene has no clip disk).
 */
export function clipTestGlsl(scene: Scene, v: SceneValues): string[] {
  if (!scene.clip) return ['  bool clipped = false;'];
  const clip = v.vec('u_clip', [scene.clip.c[0], scene.clip.c[1], scene.clip.r]);
  return [
    `  vec3 clip = ${clip};`,
    '  float cx = w.x - clip.x;',
    '  float cy = w.y - clip.y;',
    '  bool clipped = cx * cx + cy * cy > clip.z * clip.z;',
  ];
}

/** Whether the sample needs the tile-edge distance: edges, or the limit-set estimate. */
export const needsEdgeDistance = (scene: Scene): boolean =>
  scene.tile.edgeWidth > 0 ||
  scene.tile.coloring.mode === 'limit-set' ||
  (scene.tile.coloring.mode === 'measure' && scene.tile.coloring.measure === 'edge');

/** The trap circle of an orbit-trap colouring, else null. */
export const trapOf = (scene: Scene): Circle | null =>
  scene.tile.coloring.mode === 'measure' && scene.tile.coloring.measure === 'trap'
    ? scene.tile.coloring.trap
    : null;

/** `float orbitTrapDistance(vec2 p, vec3 trap)`: colour.ts orbitTrapDistance, ||p − c| − r|. */
export const orbitTrapDistanceGlsl = glslFunction(
  'orbitTrapDistance',
  `
float orbitTrapDistance(vec2 p, vec3 trap) {
  return abs(length(p - trap.xy) - trap.z);
}`,
);

/** `float colourFormula(vec2 p, int depth, float s)`: colour.ts colourFormulaValue's twin. */
const colourFormulaGlsl = (text: string): GlslFunction =>
  finiteFormulaFunction('colourFormula', 'vec2 p, int depth, float s', text, COLOUR_NAMES, {
    z: 'p',
    x: 'p.x',
    y: 'p.y',
    n: 'float(depth)',
    s: 's',
  });

/** The GLSL expression of colour.ts measureValue (every input in scope in shadeSample). */
function measureExpr(measure: Measure): string {
  switch (measure) {
    case 'x':
      return 'p.x';
    case 'y':
      return 'p.y';
    case 'radius':
      return 'length(p)';
    case 'argument':
      return `atan(p.y, p.x) / ${floatLiteral(2 * Math.PI)}`;
    case 'edge':
      return 'edgeWorld';
    case 'speed':
      return 'log(s)';
    case 'trap':
      return 'trap';
    case 'formula':
      return 'colourFormula(p, depth, s)';
  }
}

/**
 * `float farDistance(vec2 p, vec3 far)`: far-disk.ts farDistance, R > ρ ? (R − ρ)·R/ρ : 0 with
 * far = (o.x, o.y, ρ).
 */
export const farDistanceGlsl = glslFunction(
  'farDistance',
  `
float farDistance(vec2 p, vec3 far) {
  float dx = p.x - far.x;
  float dy = p.y - far.y;
  float big = sqrt(dx * dx + dy * dy);
  return big > far.z ? ((big - far.z) * big) / far.z : 0.0;
}`,
);

/**
 * `vec4 shadeSample(vec2 w, float pixelWorld, float bgAlpha)`: raster.ts's per-sample body —
 * clip test, IIS run (stopping at seeds), edge distance in pixels (max(d, far distance) / s /
 * pixelWorld), the measure (measure mode), shade (its colour in `space`); alpha is bgAlpha on the background outside the clip
 * disk, else 1. Returns shade's dependencies for the assembler.
 */
export function shadeSampleGlsl(
  scene: Scene,
  v: SceneValues,
  seeds: SeedsGlsl | null,
  space: ColourSpace = 'linear',
): GlslFunction {
  const limitSet = scene.tile.coloring.mode === 'limit-set';
  const edges = needsEdgeDistance(scene);
  const lines = ['vec4 shadeSample(vec2 w, float pixelWorld, float bgAlpha) {', ...clipTestGlsl(scene, v)];
  lines.push('  vec2 p = w;', '  float s = 1.0;', '  int depth = 0;', '  int seed = -1;');
  const trap = trapOf(scene);
  if (trap) lines.push(`  float trap = ${GLSL_FAR};`);
  const runArgs = ['p', 's', 'depth', ...(seeds ? ['seed'] : []), ...(trap ? ['trap'] : [])];
  lines.push(
    `  bool escaped = clipped ? false : runIis(${runArgs.join(', ')});`,
    `  float edgePixels = ${GLSL_FAR};`,
    `  float limitPixels = ${GLSL_FAR};`,
  );
  const coloring = scene.tile.coloring;
  const edgeMeasure = coloring.mode === 'measure' && coloring.measure === 'edge';
  if (edgeMeasure) lines.push(`  float edgeWorld = ${GLSL_FAR};`);
  const deps: GlslFunction[] = [];
  if (edges) {
    const far = farDisk(scene.elements);
    const reach = limitSet ? limitReach(scene.elements) : null;
    lines.push('  if (escaped) {');
    if (far) {
      const f = v.vec('u_farDisk', [far.c[0], far.c[1], far.r]);
      lines.push(`    float d = max(sceneBoundaryDistance(p), farDistance(p, ${f}));`);
      deps.push(farDistanceGlsl);
    } else lines.push('    float d = sceneBoundaryDistance(p);');
    lines.push('    edgePixels = d / s / pixelWorld;');
    if (edgeMeasure) lines.push('    edgeWorld = d;');
    if (reach !== null)
      lines.push(`    limitPixels = (d + ${v.float('u_limitReach', reach)}) / s / pixelWorld;`);
    lines.push('  }');
  }
  const shadeArgs = ['clipped', 'escaped', 'depth', 'edgePixels', 'p', 'limitPixels', 'seed'];
  if (coloring.mode === 'measure') {
    if (coloring.measure === 'formula') deps.push(colourFormulaGlsl(coloring.formula ?? '0'));
    lines.push(`  float measure = ${measureExpr(coloring.measure)};`);
    shadeArgs.push('measure');
  }
  lines.push(`  return vec4(shade(${shadeArgs.join(', ')}), clipped ? bgAlpha : 1.0);`, '}');
  return glslFunction('shadeSample', lines.join('\n'), [
    ...deps,
    ...(seeds ? [seeds.seedAt] : []),
    shadeGlsl(scene.tile, v, seeds?.seedColour ?? null, space),
  ]);
}
