import { GLSL_FAR } from '../../glsl/iis.glsl.ts';
import { floatLiteral } from '../../glsl/literal.ts';
import type { GlslFunction } from '../../glsl/snippet.ts';
import type { SourceBuilder } from '../../glsl/source.ts';
import { POLE_AT_INFINITY } from '../elements/element-3d-kind.ts';
import { ballDistanceGlsl } from '../elements/sphere-inversion.ts';
import { seedDistanceCall, seedGlslFunctions } from '../seeds-3d.ts';
import { budgetFunctions, emitBudgetWalk, hasBudgetBound } from './budget.glsl.ts';
import { emitStepBlocks, local, type PlacedWalk, walkLimit } from './placed-walk.ts';

export { type PlacedWalk, placeWalk } from './placed-walk.ts';

/** The functions the walk calls. */
export function walkFunctions(placed: PlacedWalk): GlslFunction[] {
  return [
    ...budgetFunctions(placed),
    ...seedGlslFunctions(placed.plan.scene.seeds),
    ballDistanceGlsl,
    ...placed.elements.flatMap(({ record }) => [
      ...record.glsl.deps,
      record.glsl.regionDistance,
      ...(record.glsl.endCover ? [record.glsl.endCover] : []),
      ...(record.glsl.mirror ? [record.glsl.mirror] : []),
    ]),
  ];
}

/** Seed k's distance at p. */
const seedCall = (placed: PlacedWalk, k: number): string =>
  seedDistanceCall(placed.plan.scene.seeds[k]!, k, placed.seeds[k]!.map(local));

/** min over seeds of seedDistance(p) (GLSL_FAR without seeds). */
const seedsMin = (placed: PlacedWalk): string =>
  placed.seeds.length === 0
    ? GLSL_FAR
    : placed.seeds.map((_, k) => seedCall(placed, k)).reduce((acc, e) => `min(${acc}, ${e})`);

/** Cover of element j at p: ../walk.ts coverOf's cover_j (its end cover at the final point, `atEnd`). */
function coverOf(placed: PlacedWalk, j: number, atEnd = false): string {
  const { record, rows, hull } = placed.elements[j]!;
  const fn = atEnd && record.glsl.endCover ? record.glsl.endCover : record.glsl.regionDistance;
  const region = `${fn.name}(p, ${rows.map(local).join(', ')})`;
  return hull ? `max(${region}, ballDistance(p, ${local(hull[0])}))` : region;
}

/**
 * min(max(0, seeds), cover_j for j ≠ nearest): ../walk.ts mirroredCover's L with the nearest element
 * (the GLSL int `nearest`) left out by a select.
 */
function coverExceptNearest(placed: PlacedWalk): string {
  let expr = `max(0.0, ${seedsMin(placed)})`;
  placed.elements.forEach((_, j) => {
    expr = `min(${expr}, nearest == ${j} ? ${GLSL_FAR} : ${coverOf(placed, j)})`;
  });
  return expr;
}

/**
 * Statements setting `de` to ../walk.ts endDistance: min(seeds, covers) with the nearest cover
 * raised to its mirrored cover (the image q, L_j there, carried back) — one mirror, O(n) at run time.
 * The nearest element's data is copied into `m<K>_*` as the minimum is found, so each mirror kind
 * K has ONE block (not one per element: SIMD lanes whose nearest mirrors differ would run several),
 * and that block leaves the nearest cover out with a select rather than a branch.
 */
function endDistanceStatements(placed: PlacedWalk): string[] {
  const kinds = [
    ...new Set(placed.elements.flatMap(({ record }) => (record.glsl.mirror ? [record.kind] : []))),
  ];
  const lines = [
    `  float de = max(0.0, sd);`,
    `  float second = ${GLSL_FAR};`,
    '  int nearest = -1;',
    '  int nearestKind = -1;',
  ];
  kinds.forEach((kind, k) => {
    const { record } = placed.elements.find((e) => e.record.kind === kind)!;
    for (let r = 0; r < record.glsl.vec4s; r++) lines.push(`  vec4 m${k}_${r} = vec4(0.0);`);
    lines.push(`  float m${k}_reach = ${GLSL_FAR};`);
  });
  placed.elements.forEach(({ record, rows, hull }, j) => {
    const k = kinds.indexOf(record.kind);
    const pick =
      k < 0
        ? ' nearestKind = -1;'
        : ` nearestKind = ${k};${rows.map((r, i) => ` m${k}_${i} = ${local(r)};`).join('')} m${k}_reach = ${
            hull ? `${local(hull[1])}.x` : GLSL_FAR
          };`;
    lines.push(
      `  float c${j} = ${coverOf(placed, j, true)};`,
      `  if (c${j} < de) { second = de; de = c${j}; nearest = ${j};${pick} } else second = min(second, c${j});`,
    );
  });
  kinds.forEach((kind, k) => {
    const { record } = placed.elements.find((e) => e.record.kind === kind)!;
    const data = Array.from({ length: record.glsl.vec4s }, (_, r) => `m${k}_${r}`).join(', ');
    lines.push(
      `  if (nearestKind == ${k}) {`,
      '    vec3 q;',
      '    float far;',
      `    float r2 = ${record.glsl.mirror!.name}(p, ${data}, q, far);`,
      '    vec3 pm = p;',
      '    p = q;',
      `    float lq = ${coverExceptNearest(placed)};`,
      '    p = pm;',
      `    de = max(de, r2 == 0.0 ? lq : r2 * (lq / (far * min(m${k}_reach, far + lq))));`,
      '  }',
    );
  });
  lines.push('  de = min(de, second);');
  return lines;
}

/**
 * The scene's rows as globals, `el<N>` for `u_el[N]`, filled once per pixel by `loadScene()` (which
 * main calls first). Read from the uniform array at every walk, they cost SwiftShader as much as
 * the walk's arithmetic: the Fig. 11 probe frame took 2.4× a hand-written tracer's time with the
 * rows copied into the walk's locals, 1.2× with them loaded once. Emits nothing when baked.
 */
export function emitSceneGlobals(out: SourceBuilder, placed: PlacedWalk): boolean {
  const rows = [
    ...placed.elements.flatMap((e) => [...e.rows, ...(e.hull ?? [])]),
    ...placed.seeds.flatMap((s) => [...s]),
  ].filter((r) => local(r) !== r);
  const literalLimit = /^\d+$/.test(placed.maxIter);
  if (rows.length === 0 && literalLimit) return false;
  out.push(
    ...rows.map((r) => `vec4 ${local(r)};`),
    ...(literalLimit ? [] : ['int maxIter;']),
    'void loadScene() {',
    ...rows.map((r) => `  ${local(r)} = ${r};`),
    ...(literalLimit ? [] : [`  maxIter = ${placed.maxIter};`]),
    '}',
    '',
  );
  return true;
}

/**
 * `float walk<Name>(vec3 start, out vec4 info, out vec3 fin)`. Recording: the walk also moves the
 * pole, and the function returns the safe bound.
 */
export function emitWalk(out: SourceBuilder, placed: PlacedWalk, record: boolean): void {
  const limit = walkLimit(placed);
  // The bound of a walk out of budget (budget.glsl.ts), called by traceRay.
  if (record && hasBudgetBound(placed)) emitBudgetWalk(out, placed);
  out.push(
    `float walk${record ? 'Record' : 'Plain'}(vec3 start, out vec4 info, out vec3 fin) {`,
    '  vec3 p = start;',
    '  float s = 1.0;',
    '  int depth = 0;',
    ...(record ? [`  vec3 pole = vec3(${floatLiteral(POLE_AT_INFINITY)}, 0.0, 0.0);`] : []),
    `  for (; depth < ${limit};) {`,
  );
  emitStepBlocks(out, placed, { pole: record, applied: '' });
  out.push('    break;', '  }');
  if (placed.seeds.length === 0) out.push(`  float sd = ${GLSL_FAR};`, '  int seed = -1;');
  else {
    out.push(`  float sd = ${seedCall(placed, 0)};`, '  int seed = 0;');
    placed.seeds.slice(1).forEach((_, k) => {
      out.push(
        `  float sd${k + 1} = ${seedCall(placed, k + 1)};`,
        `  if (sd${k + 1} < sd) { sd = sd${k + 1}; seed = ${k + 1}; }`,
      );
    });
  }
  out.push('  info = vec4(sd / s, float(depth), float(seed), s);', '  fin = p;');
  if (record) {
    out.push(...endDistanceStatements(placed), '  return de / (s * (1.0 + de / length(p - pole)));');
  } else out.push('  return 0.0;');
  out.push('}');
}
