#version 300 es
// The Apollonian gasket of examples/apollonian-gasket, written by hand for this one scene: the
// "physical limit" the generated shader is measured against (tests/bench). Same frame uniforms and
// the same probe output as compile(scene, { variant: 'probe' }): (depth, final.x, final.y, escaped).
precision highp float;
precision highp int;

uniform vec2 u_resolution;
uniform vec2 u_pixelOffset;
uniform vec3 u_view;
uniform vec2 u_jitter;
out vec4 outProbe;

const int MAX_ITER = 300;
// The four inversion circles through the kissing points, in graph order: (centre, radius²).
const vec3 CIRCLES[4] = vec3[4](
  vec3(-1.732053943343968, 1.00000157731464, 3.000010862655876),
  vec3(0.0, 3.739823947190857e-7, 0.07179686701755719),
  vec3(0.0, -1.9999970567332186, 2.999990470833319),
  vec3(1.732053943343968, 1.00000157731464, 3.000010862655876)
);

/** Inverts p in the first circle that holds it; false when p is in the tile (outside all four). */
bool invertFirst(inout vec2 p) {
  for (int k = 0; k < 4; k++) {
    vec2 q = p - CIRCLES[k].xy;
    float qq = dot(q, q);
    if (qq < CIRCLES[k].z) {
      p = CIRCLES[k].xy + q * (CIRCLES[k].z / qq);
      return true;
    }
  }
  return false;
}

void main() {
  vec2 px = floor(gl_FragCoord.xy) + u_pixelOffset;
  vec2 p = u_view.xy + (px + u_jitter - 0.5 * u_resolution) / u_resolution.y * u_view.z;
  int depth = 0;
  bool escaped = false;
  for (; depth < MAX_ITER; depth++) {
    if (!invertFirst(p)) {
      escaped = true;
      break;
    }
  }
  if (!escaped) {
    // At MAX_ITER: escaped only if p is already in the tile.
    vec2 probe = p;
    escaped = !invertFirst(probe);
  }
  outProbe = vec4(float(depth), p, escaped ? 1.0 : 0.0);
}
