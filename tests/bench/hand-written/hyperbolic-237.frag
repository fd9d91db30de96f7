#version 300 es
// The (2,3,7) triangle group of examples/hyperbolic-237, written by hand for this one scene: the
// "physical limit" the generated shader is measured against (tests/bench). Same frame uniforms and
// the same probe output as compile(scene, { variant: 'probe' }): (depth, final.x, final.y, escaped).
// With COLOUR defined (tests/bench/hand-written/index.ts adds the line) it draws the example's
// picture instead, as compile(scene, { variant: 'color' }) does: linear light, or with SRGB_OUTPUT
// too the sRGB colours written as they are (the one-sample Shadertoy image).
precision highp float;
precision highp int;

uniform vec2 u_resolution;
uniform vec2 u_pixelOffset;
uniform vec3 u_view;
uniform vec2 u_jitter;
#ifdef COLOUR
uniform float u_bgAlpha;
out vec4 outColor;
// The tile's colours (#f3ead7, #1f2f4f; background #0c0f16; limit set #050508).
#ifdef SRGB_OUTPUT
const vec3 EVEN = vec3(243.0, 234.0, 215.0) / 255.0;
const vec3 ODD = vec3(31.0, 47.0, 79.0) / 255.0;
const vec3 BACKGROUND = vec3(12.0, 15.0, 22.0) / 255.0;
const vec3 LIMIT = vec3(5.0, 5.0, 8.0) / 255.0;
#else
// Decoded to linear light once, by hand (the sRGB transfer function, shader-gen/srgb.ts).
const vec3 EVEN = vec3(0.8962693533742664, 0.8227857543962835, 0.6795424696330938);
const vec3 ODD = vec3(0.013702083047289686, 0.028426039504420793, 0.07818742180518633);
const vec3 BACKGROUND = vec3(0.003676507324047436, 0.004776953480693729, 0.008023192985384994);
const vec3 LIMIT = vec3(0.0015176349177441874, 0.0015176349177441874, 0.0024282158683907);
#endif
#else
out vec4 outProbe;
#endif

const int MAX_ITER = 200;
// Mirror 2: the line through 0 at angle π/7, kept side dot(p, N2) >= 0, N2 = (sin π/7, −cos π/7).
const vec2 N2 = vec2(0.4338837391175581, -0.9009688679024191);
// Mirror 3: the circle orthogonal to the unit circle (math.md): u = ((cos π/3 + cos π/7 cos π/2)
// / sin π/7, cos π/2), R² = 1 / (|u|² − 1), centre R·u; kept side outside.
const vec2 C = vec2(2.0121921726123224, 0.0);
const float R2 = 3.048917339522299; // R² = 1.7461149273522345²

bool inMirror(vec2 p) {
  vec2 q = p - C;
  return p.y < 0.0 || dot(p, N2) < 0.0 || dot(q, q) < R2;
}

void main() {
  vec2 px = floor(gl_FragCoord.xy) + u_pixelOffset;
  vec2 p = u_view.xy + (px + u_jitter - 0.5 * u_resolution) / u_resolution.y * u_view.z;
#ifdef COLOUR
  // Outside the unit disk (the clip): the background.
  if (dot(p, p) > 1.0) {
    outColor = vec4(BACKGROUND, u_bgAlpha);
    return;
  }
#endif
  int depth = 0;
  bool escaped = false;
  // Reflect in the first mirror whose inside holds p and start over, until none does.
  for (; depth < MAX_ITER; depth++) {
    if (p.y < 0.0) {
      p.y = -p.y;
      continue;
    }
    float h = dot(p, N2);
    if (h < 0.0) {
      p -= 2.0 * h * N2;
      continue;
    }
    vec2 q = p - C;
    float qq = dot(q, q);
    if (qq < R2) {
      p = C + q * (R2 / qq);
      continue;
    }
    escaped = true;
    break;
  }
  if (!escaped) escaped = !inMirror(p); // at MAX_ITER: escaped only if p is in the tile
#ifdef COLOUR
  outColor = vec4(escaped ? (depth % 2 == 0 ? EVEN : ODD) : LIMIT, 1.0);
#else
  outProbe = vec4(float(depth), p, escaped ? 1.0 : 0.0);
#endif
}
