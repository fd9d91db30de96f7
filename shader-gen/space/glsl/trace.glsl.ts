/**
 * The GLSL march and shading, twins of ../trace-3d.ts and ../shade-3d.ts line by line
 * (docs/math-3d.md "§9 The sphere tracer: march, hit, shading"): rayInterval (bounding ball, or a far distance for unbounded orbits), traceRay (hit on the
 * seed-image distance, step max(deScale·DE, ε)), and shadeHit (tetrahedral normal, Coloring3d,
 * Blinn–Phong, ambient occlusion, soft shadow). Scene values come through `v` (uniforms or literals).
 */

import type { Coloring3d, Scene3d } from '../../../nodes/core/scene-3d.ts';
import { COLOUR_3D_NAMES } from '../../../nodes/formula/names.ts';
import { cosinePaletteGlsl, hsvToRgbGlsl, toLinearGlsl } from '../../glsl/colour.glsl.ts';
import { finiteFormulaFunction } from '../../glsl/formula.glsl.ts';
import { floatLiteral, intLiteral } from '../../glsl/literal.ts';
import { type GlslFunction, glslFunction } from '../../glsl/snippet.ts';
import type { SceneValues } from '../../glsl/values.ts';
import { type TracePlan, UNBOUNDED_REACH } from '../plan.ts';
import { seedSize } from '../seeds-3d.ts';
import { AO_SAMPLES, AO_STEP, SHADOW_K, SHADOW_STEPS } from '../shade-3d.ts';
import { HIT_PIXELS, NEAR } from '../trace-3d.ts';
import { budgetBoundIn } from './budget.glsl.ts';

/**
 * `bool <name>(vec3 o, vec3 d, out vec2 span)`: ../trace-3d.ts rayInterval over the ball `bounds`
 * (a vec4 (centre, radius) expression); `mode` > 0.5 means unbounded (a far span from the origin).
 */
export function rayIntervalGlsl(name: string, bounds: string, mode: string): GlslFunction {
  return glslFunction(
    name,
    `
bool ${name}(vec3 o, vec3 d, out vec2 span) {
  vec4 b = ${bounds};
  vec3 oc = o - b.xyz;
  span = vec2(0.0, length(oc) + ${floatLiteral(UNBOUNDED_REACH)} * b.w);
  if (${mode} > 0.5) return true;
  float bb = dot(oc, d);
  float disc = bb * bb - (dot(oc, oc) - b.w * b.w);
  if (disc <= 0.0) return false;
  float h = sqrt(disc);
  if (-bb + h <= 0.0) return false;
  span = vec2(max(0.0, -bb - h), -bb + h);
  return true;
}`,
  );
}

/** rayInterval, hitTolerance and traceRay over the scene's bounds and march settings. */
export function traceGlsl(plan: TracePlan, v: SceneValues): GlslFunction {
  const { center: c, radius: r } = plan.bounds;
  const bounds = v.vec('u_bounds', [c[0], c[1], c[2], r]);
  const mode = v.float('u_boundsMode', plan.bounded ? 0 : 1);
  const steps = v.int('u_marchSteps', plan.scene.marchSteps);
  const deScale = v.float('u_deScale', plan.scene.deScale);
  const interval = rayIntervalGlsl('rayInterval', bounds, mode);
  const tolerance = glslFunction(
    'hitTolerance',
    `
float hitTolerance(float angle, float t) {
  return ${floatLiteral(HIT_PIXELS)} * angle * max(t, ${floatLiteral(NEAR)} * ${bounds}.w);
}`,
  );
  const hasSeeds = plan.scene.seeds.length > 0;
  // The bound of a walk out of budget, where the program has it (budget.glsl.ts budgetBoundIn).
  const budget = budgetBoundIn(plan);
  return glslFunction(
    'traceRay',
    `
bool traceRay(vec3 o, vec3 d, float angle, float tStart, out float t, out vec4 info, out vec3 fin) {
  t = 0.0;
  info = vec4(0.0, 0.0, -1.0, 1.0);
  fin = vec3(0.0);
  vec2 span;
  if (${hasSeeds ? '!rayInterval(o, d, span)' : 'true'}) return false;
  t = max(span.x, tStart);
  int steps = ${steps};
  float deScale = ${deScale};
  for (int i = 0; i < steps; ++i) {
    float de = walkRecord(o + d * t, info, fin);
    float eps = hitTolerance(angle, t);
    if (info.x < eps) return true;${budget ? '\n    de = budgetedDe(o + d * t, info, de);' : ''}
    t += max(deScale * de, eps);
    if (t > span.y) return false;
  }
  return false;
}`,
    [interval, tolerance],
  );
}

const rgbToHsvGlsl = glslFunction(
  'rgbToHsv',
  `
vec3 rgbToHsv(vec3 c) {
  float mx = max(c.r, max(c.g, c.b));
  float mn = min(c.r, min(c.g, c.b));
  float delta = mx - mn;
  float h = 0.0;
  if (delta > 0.0) {
    if (mx == c.r) h = (c.g - c.b) / delta / 6.0;
    else if (mx == c.g) h = ((c.b - c.r) / delta + 2.0) / 6.0;
    else h = ((c.r - c.g) / delta + 4.0) / 6.0;
  }
  return vec3(fract(h), mx > 0.0 ? delta / mx : 0.0, mx);
}`,
);

const fieldGlsl = glslFunction(
  'colourField',
  `
vec3 colourField(vec3 p, float scale) {
  return 0.5 + 0.5 * cos(${floatLiteral(2 * Math.PI)} * p / scale);
}`,
);

/** `vec3 baseColour(vec4 seed, float depth, vec3 point, vec3 fin)`: ../shade-3d.ts baseColour (sRGB). */
function baseColourGlsl(coloring: Coloring3d, v: SceneValues): GlslFunction {
  const head = 'vec3 baseColour(vec4 seed, float depth, vec3 point, vec3 fin) {';
  switch (coloring.mode) {
    case 'depth-wheel': {
      const step = v.float('u_colorStep', coloring.step);
      return glslFunction(
        'baseColour',
        `${head}\n  vec3 hsv = rgbToHsv(seed.rgb);\n  return hsvToRgb(hsv.x + ${step} * depth, hsv.y, hsv.z);\n}`,
        [rgbToHsvGlsl, hsvToRgbGlsl],
      );
    }
    case 'cosine': {
      const [a, b, c, d] = (['a', 'b', 'c', 'd'] as const).map((k) =>
        v.vec(`u_palette${k.toUpperCase()}`, coloring[k]),
      );
      const step = v.float('u_colorStep', coloring.step);
      return glslFunction(
        'baseColour',
        `${head}\n  return cosinePalette(${a}, ${b}, ${c}, ${d}, depth * ${step});\n}`,
        [cosinePaletteGlsl],
      );
    }
    case 'surface':
    case 'final-point': {
      const scale = v.float('u_colorScale', coloring.scale);
      const at = coloring.mode === 'surface' ? 'point' : 'fin';
      return glslFunction('baseColour', `${head}\n  return colourField(${at}, ${scale});\n}`, [fieldGlsl]);
    }
    case 'distance':
    case 'argument':
    case 'formula': {
      // ../shade-3d.ts measureColour3d: t = offset + frequency·m at the hit point.
      const [a, b, c, d] = (['a', 'b', 'c', 'd'] as const).map((k) =>
        v.vec(`u_palette${k.toUpperCase()}`, coloring[k]),
      );
      const wheel = v.float('u_colorWheel', coloring.wheel ? 1 : 0);
      const frequency = v.float('u_colorFrequency', coloring.frequency);
      const offset = v.float('u_colorOffset', coloring.offset);
      const formula = coloring.mode === 'formula' ? colourFormula3dGlsl(coloring.formula ?? '0') : null;
      const m =
        coloring.mode === 'distance'
          ? 'length(point)'
          : formula
            ? 'colourFormula3d(point, depth)'
            : `atan(point.y, point.x) / ${floatLiteral(2 * Math.PI)}`;
      return glslFunction(
        'baseColour',
        `${head}
  float t = ${offset} + ${frequency} * ${m};
  if (${wheel} < 0.5) return cosinePalette(${a}, ${b}, ${c}, ${d}, t);
  vec3 hsv = rgbToHsv(seed.rgb);
  return hsvToRgb(hsv.x + t, hsv.y, hsv.z);
}`,
        [cosinePaletteGlsl, rgbToHsvGlsl, hsvToRgbGlsl, ...(formula ? [formula] : [])],
      );
    }
  }
}

/** `float colourFormula3d(vec3 point, float depth)`: ../shade-3d.ts colourFormula3d's twin. */
const colourFormula3dGlsl = (text: string): GlslFunction =>
  finiteFormulaFunction('colourFormula3d', 'vec3 point, float depth', text, COLOUR_3D_NAMES, {
    x: 'point.x',
    y: 'point.y',
    z: 'point.z',
    n: 'depth',
  });

/** `vec4 seedData(float k)`: seed k's sRGB colour and size (../seeds-3d.ts seedSize). */
function seedDataGlsl(scene: Scene3d, v: SceneValues): GlslFunction {
  const rows = scene.seeds.map((s, k) => v.vec(`u_seed${k}`, [...s.color, seedSize(s)]));
  const lines = ['vec4 seedData(float k) {'];
  rows.slice(0, -1).forEach((r, k) => {
    lines.push(`  if (k < ${floatLiteral(k + 0.5)}) return ${r};`);
  });
  lines.push(`  return ${rows.at(-1) ?? 'vec4(1.0)'};`, '}');
  return glslFunction('seedData', lines.join('\n'));
}

/**
 * `vec3 shadeHit(vec3 o, vec3 d, float angle, float t, vec4 info, vec3 fin, out vec3 n, out vec3 base)`:
 * ../shade-3d.ts surfaceAt (the normal n and linear base colour, out) and shadeHit.
 */
export function shadeGlsl(plan: TracePlan, v: SceneValues): GlslFunction {
  const { lighting: l, coloring } = plan.scene;
  const dir = v.vec('u_lightDirection', l.direction);
  const terms = v.vec('u_lightTerms', [l.ambient, l.diffuse, l.specular, l.shininess]);
  const extra = v.vec('u_lightShadow', [l.occlusion, l.shadow]);
  const bounds = 'u_bounds';
  const radius = v.baked ? floatLiteral(plan.bounds.radius) : `${bounds}.w`;
  const deScale = v.baked ? floatLiteral(plan.scene.deScale) : 'u_deScale';
  const imageDistance = glslFunction(
    'imageDistance',
    `
float imageDistance(vec3 p) {
  vec4 info;
  vec3 fin;
  walkPlain(p, info, fin);
  return info.x;
}`,
  );
  return glslFunction(
    'shadeHit',
    `
vec3 shadeHit(vec3 o, vec3 d, float angle, float t, vec4 info, vec3 fin, out vec3 n, out vec3 base) {
  vec3 p = o + d * t;
  float eps = hitTolerance(angle, t);
  // The tetrahedron's corners (1,−1,−1), (−1,−1,1), (−1,1,−1), (1,1,1) in a loop: one call site of
  // the walk instead of four, since a software WebGL (SwiftShader) compiles every call site anew.
  vec3 g = vec3(0.0);
  for (int k = 0; k < 4; ++k) {
    vec3 e = vec3(k == 0 || k == 3 ? 1.0 : -1.0, k >= 2 ? 1.0 : -1.0, k == 1 || k == 3 ? 1.0 : -1.0);
    g += e * imageDistance(p + e * eps);
  }
  float glen = length(g);
  n = glen > 0.0 ? g / glen : vec3(0.0);
  vec4 seed = seedData(info.z);
  base = toLinear(baseColour(seed, info.y, p, fin));
  vec3 l = normalize(${dir});
  vec4 terms = ${terms};
  vec2 extra = ${extra};
  float diff = max(dot(n, l), 0.0);
  vec3 hv = normalize(l - d);
  float spec = diff > 0.0 ? pow(max(dot(n, hv), 0.0), terms.w) : 0.0;
  float aoStep = max(${floatLiteral(AO_STEP)} * seed.w / info.w, eps);
  float occ = 0.0;
  float weights = 0.0;
  for (int k = 1; k <= ${intLiteral(AO_SAMPLES)}; ++k) {
    float hk = float(k) * aoStep;
    float w = pow(0.5, float(k));
    occ += w * clamp((hk - imageDistance(p + n * hk)) / hk, 0.0, 1.0);
    weights += w;
  }
  float ao = 1.0 - extra.x * (occ / weights);
  float res = 1.0;
  if (extra.y > 0.0 && diff > 0.0) {
    vec3 from = p + n * (2.0 * eps);
    float ts = 2.0 * eps;
    for (int i = 0; i < ${intLiteral(SHADOW_STEPS)}; ++i) {
      vec4 si;
      vec3 sf;
      float de = walkRecord(from + l * ts, si, sf);
      float e = hitTolerance(angle, t + ts);
      if (si.x < e) {
        res = 0.0;
        break;
      }
      res = min(res, ${floatLiteral(SHADOW_K)} * de / ts);
      ts += max(${deScale} * de, e);
      if (ts > 2.0 * ${radius}) break;
    }
  }
  float sh = 1.0 - extra.y * (1.0 - clamp(res, 0.0, 1.0));
  float lit = terms.x * ao + terms.y * diff * sh;
  return base * lit + vec3(terms.z * spec * sh);
}`,
    [imageDistance, seedDataGlsl(plan.scene, v), baseColourGlsl(coloring, v), toLinearGlsl],
  );
}
