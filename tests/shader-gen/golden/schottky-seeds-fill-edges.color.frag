#version 300 es
precision highp float;
precision highp int;

// Frame uniforms (set by the runtime).
uniform vec2 u_resolution; // full image size in pixels
uniform vec2 u_pixelOffset; // offset of this framebuffer within the full image (tiled export)
uniform vec3 u_view; // view centre x, y and scale (world height of the image)
uniform vec2 u_jitter; // sub-pixel sample offset in [0,1)² (view.ts sampleOffset)
uniform float u_bgAlpha; // alpha of the background outside the clip disk (1; 0 for transparent export)
// Scene uniforms (values; changing them needs no recompile).
uniform vec3 u_background;
uniform vec3 u_edgeColor;
uniform float u_edgeWidth;
uniform vec4 u_el[5];
uniform vec3 u_farDisk;
uniform vec3 u_fill;
uniform vec3 u_limitColor;
uniform int u_maxIterations;
uniform vec3 u_paletteA;
uniform vec3 u_paletteB;
uniform vec3 u_paletteC;
uniform vec3 u_paletteD;
uniform float u_paletteStep;
uniform vec4 u_seed0;
uniform vec4 u_seed1;
uniform vec3 u_seedColor0;
uniform vec2 u_seedRot1;
// Pictures (textures; the runtime binds texture unit N to u_imageN).
uniform sampler2D u_image0;
out vec4 outColor; // linear RGB; alpha u_bgAlpha on the background

bool inRegion(vec4 g, vec2 p) {
  float dx = p.x - g.x;
  float dy = p.y - g.y;
  float d2 = dx * dx + dy * dy;
  float r2 = g.z * g.z;
  return g.w > 0.5 ? d2 > r2 : d2 < r2;
}

void invertOffset(inout vec2 p, inout float s, vec2 c, float r, float r2, float dx, float dy, float d2) {
  float k = min(r2 / d2, 1e+36);
  p = vec2(c.x + (dx + r * 1e-18) * k, c.y + dy * k);
  s *= k;
}

void invertState(inout vec2 p, inout float s, vec2 c, float r, float r2) {
  float dx = p.x - c.x;
  float dy = p.y - c.y;
  invertOffset(p, s, c, r, r2, dx, dy, dx * dx + dy * dy);
}

bool mobiusInside(vec2 p, vec4 d0, vec4 d1, vec4 d2, vec4 d3) {
  return inRegion(d2, p) || inRegion(d3, p);
}

float regionBoundaryDistance(vec4 g, vec2 p) {
  return abs(length(p - g.xy) - g.z);
}

float mobiusBoundaryDistance(vec2 p, vec4 d0, vec4 d1, vec4 d2, vec4 d3) {
  return min(regionBoundaryDistance(d2, p), regionBoundaryDistance(d3, p));
}

bool inversionInside(vec2 p, vec4 d0) {
  float dx = p.x - d0.x;
  float dy = p.y - d0.y;
  return dx * dx + dy * dy < d0.w;
}

float inversionBoundaryDistance(vec2 p, vec4 d0) {
  return abs(length(p - d0.xy) - d0.z);
}

float farDistance(vec2 p, vec3 far) {
  float dx = p.x - far.x;
  float dy = p.y - far.y;
  float big = sqrt(dx * dx + dy * dy);
  return big > far.z ? ((big - far.z) * big) / far.z : 0.0;
}

bool seedDiskInside(vec2 p, vec4 d) {
  return (p.x - d.x) * (p.x - d.x) + (p.y - d.y) * (p.y - d.y) < d.z * d.z;
}

vec2 placeUv(vec4 rect, vec2 rot, vec2 p) {
  float dx = p.x - rect.x;
  float dy = p.y - rect.y;
  float lx = rot.x * dx + rot.y * dy;
  float ly = -rot.y * dx + rot.x * dy;
  return vec2(lx / rect.z + 0.5, 0.5 - ly / rect.w);
}

int seedAt(vec2 p, vec4 a0, vec4 a1, vec2 a2) {
  if (seedDiskInside(p, a0)) return 0;
  {
    vec2 uv = placeUv(a1, a2, p);
    if (uv.x > 0.0 && uv.x < 1.0 && uv.y > 0.0 && uv.y < 1.0) return 1;
  }
  return -1;
}

vec3 seedColour(int seed, vec2 p) {
  if (seed == 0) return u_seedColor0;
  if (seed == 1) return textureLod(u_image0, placeUv(u_seed1, u_seedRot1, p), 0.0).rgb;
  return vec3(0.0);
}

float srgbToLinear(float c) {
  return c <= 0.04045 ? c / 12.92 : pow((c + 0.055) / 1.055, 2.4);
}

vec3 toLinear(vec3 c) {
  return vec3(srgbToLinear(c.r), srgbToLinear(c.g), srgbToLinear(c.b));
}

vec3 cosinePalette(vec3 a, vec3 b, vec3 c, vec3 d, float t) {
  return clamp(a + b * cos(6.283185307179586 * (c * t + d)), 0.0, 1.0);
}

vec3 depthColour(int depth) {
  return cosinePalette(u_paletteA, u_paletteB, u_paletteC, u_paletteD, float(depth) * u_paletteStep);
}

vec3 finalColour(int depth, vec2 p) {
  return toLinear(depthColour(depth));
}

vec3 shade(bool clipped, bool escaped, int depth, float edgePixels, vec2 p, float limitPixels, int seed) {
  if (clipped) return u_background;
  if (seed >= 0) return seedColour(seed, p);
  if (!escaped) return u_limitColor;
  vec3 base = depth == 0 ? u_fill : finalColour(depth, p);
  float t = clamp(edgePixels - u_edgeWidth / 2.0 + 0.5, 0.0, 1.0);
  vec3 edge = u_edgeColor;
  return edge + (base - edge) * t;
}

vec2 pixelToWorld(vec3 view, vec2 size, vec2 px, vec2 o) {
  return vec2(view.x + ((px.x + o.x - size.x / 2.0) / size.y) * view.z,
              view.y + ((px.y + o.y - size.y / 2.0) / size.y) * view.z);
}

bool runIis(inout vec2 p, inout float s, inout int depth, inout int seed) {
  vec4 el0 = u_el[0];
  vec4 el1 = u_el[1];
  vec4 el2 = u_el[2];
  vec4 el3 = u_el[3];
  vec4 el4 = u_el[4];
  vec4 seedArg0 = u_seed0;
  vec4 seedArg1 = u_seed1;
  vec2 seedArg2 = u_seedRot1;
  int maxIter = u_maxIterations;
  for (; depth < maxIter; ++depth) {
    seed = seedAt(p, seedArg0, seedArg1, seedArg2);
    if (seed >= 0) return false;
#line 1 1
    { // mobius
      vec4 d0 = el0;
      vec4 d1 = el1;
      vec4 d2 = el2;
      vec4 d3 = el3;
      if (inRegion(d2, p)) {
        invertState(p, s, d0.xy, d0.z, d0.z * d0.z);
        invertState(p, s, d1.xy, d1.z, d1.z * d1.z);
        continue;
      } else if (inRegion(d3, p)) {
        invertState(p, s, d1.xy, d1.z, d1.z * d1.z);
        invertState(p, s, d0.xy, d0.z, d0.z * d0.z);
        continue;
      }
    }
#line 1 2
    { // inversion
      vec4 d0 = el4;
      float dx = p.x - d0.x;
      float dy = p.y - d0.y;
      float d2 = dx * dx + dy * dy;
      if (!(d2 >= d0.w)) {
        invertOffset(p, s, d0.xy, d0.z, d0.w, dx, dy, d2);
        continue;
      }
    }
#line 185 0
    return true;
  }
  seed = seedAt(p, seedArg0, seedArg1, seedArg2);
  if (seed >= 0) return false;
  // depth ≥ maxIter: escaped only if no element holds p.
#line 1 1
  if (mobiusInside(p, el0, el1, el2, el3)) return false;
#line 1 2
  if (inversionInside(p, el4)) return false;
#line 195 0
  return true;
}

float sceneBoundaryDistance(vec2 p) {
  float d = 3.0e38;
#line 1 1
  d = min(d, mobiusBoundaryDistance(p, u_el[0], u_el[1], u_el[2], u_el[3]));
#line 1 2
  d = min(d, inversionBoundaryDistance(p, u_el[4]));
#line 205 0
  return d;
}

vec4 shadeSample(vec2 w, float pixelWorld, float bgAlpha) {
  bool clipped = false;
  vec2 p = w;
  float s = 1.0;
  int depth = 0;
  int seed = -1;
  bool escaped = clipped ? false : runIis(p, s, depth, seed);
  float edgePixels = 3.0e38;
  float limitPixels = 3.0e38;
  if (escaped) {
    float d = max(sceneBoundaryDistance(p), farDistance(p, u_farDisk));
    edgePixels = d / s / pixelWorld;
  }
  return vec4(shade(clipped, escaped, depth, edgePixels, p, limitPixels, seed), clipped ? bgAlpha : 1.0);
}

void main() {
  vec2 px = floor(gl_FragCoord.xy) + u_pixelOffset;
  vec2 w = pixelToWorld(u_view, u_resolution, px, u_jitter);
  outColor = shadeSample(w, u_view.z / u_resolution.y, u_bgAlpha);
}
