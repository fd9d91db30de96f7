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
// The four inversion circles through the kissing points, in graph order: centre Ck, radius² Rk.
const vec2 C1 = vec2(-1.732053943343968, 1.00000157731464);
const float R1 = 3.000010862655876;
const vec2 C2 = vec2(0.0, 3.739823947190857e-7);
const float R2 = 0.07179686701755719;
const vec2 C3 = vec2(0.0, -1.9999970567332186);
const float R3 = 2.999990470833319;
const vec2 C4 = vec2(1.732053943343968, 1.00000157731464);
const float R4 = 3.000010862655876;

/** Whether p is inside one of the four circles (not in the tile). */
bool inCircle(vec2 p) {
  vec2 q1 = p - C1;
  vec2 q2 = p - C2;
  vec2 q3 = p - C3;
  vec2 q4 = p - C4;
  return dot(q1, q1) < R1 || dot(q2, q2) < R2 || dot(q3, q3) < R3 || dot(q4, q4) < R4;
}

void main() {
  vec2 px = floor(gl_FragCoord.xy) + u_pixelOffset;
  vec2 p = u_view.xy + (px + u_jitter - 0.5 * u_resolution) / u_resolution.y * u_view.z;
  int depth = 0;
  bool escaped = false;
  // Invert in the first circle that holds p and start over, until none does.
  for (; depth < MAX_ITER; depth++) {
    vec2 q = p - C1;
    float qq = dot(q, q);
    if (qq < R1) {
      p = C1 + q * (R1 / qq);
      continue;
    }
    q = p - C2;
    qq = dot(q, q);
    if (qq < R2) {
      p = C2 + q * (R2 / qq);
      continue;
    }
    q = p - C3;
    qq = dot(q, q);
    if (qq < R3) {
      p = C3 + q * (R3 / qq);
      continue;
    }
    q = p - C4;
    qq = dot(q, q);
    if (qq < R4) {
      p = C4 + q * (R4 / qq);
      continue;
    }
    escaped = true;
    break;
  }
  if (!escaped) escaped = !inCircle(p); // at MAX_ITER: escaped only if p is in the tile
  outProbe = vec4(float(depth), p, escaped ? 1.0 : 0.0);
}
