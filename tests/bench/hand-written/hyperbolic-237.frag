#version 300 es
// The (2,3,7) triangle group of examples/hyperbolic-237, written by hand for this one scene: the
// "physical limit" the generated shader is measured against (tests/bench). Same frame uniforms and
// the same probe output as compile(scene, { variant: 'probe' }): (depth, final.x, final.y, escaped).
precision highp float;
precision highp int;

uniform vec2 u_resolution;
uniform vec2 u_pixelOffset;
uniform vec3 u_view;
uniform vec2 u_jitter;
out vec4 outProbe;

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
  outProbe = vec4(float(depth), p, escaped ? 1.0 : 0.0);
}
