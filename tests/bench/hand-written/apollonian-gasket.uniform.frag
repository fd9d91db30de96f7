#version 300 es
// The Apollonian gasket of examples/apollonian-gasket written by hand, with the scene's values as
// uniforms (what a drag changes): the reference for the generated uniform program. Same data as
// compile()'s u_el rows — circle k: (c.x, c.y, r, r²) — copied into locals before the loop
// (SwiftShader reloads a uniform at every use inside a loop).
precision highp float;
precision highp int;

uniform vec2 u_resolution;
uniform vec2 u_pixelOffset;
uniform vec3 u_view;
uniform vec2 u_jitter;
uniform vec4 u_el[4];
uniform int u_maxIterations;
out vec4 outProbe;

void main() {
  vec2 C1 = u_el[0].xy, C2 = u_el[1].xy, C3 = u_el[2].xy, C4 = u_el[3].xy;
  float R1 = u_el[0].w, R2 = u_el[1].w, R3 = u_el[2].w, R4 = u_el[3].w;
  int maxIter = u_maxIterations;
  vec2 px = floor(gl_FragCoord.xy) + u_pixelOffset;
  vec2 p = u_view.xy + (px + u_jitter - 0.5 * u_resolution) / u_resolution.y * u_view.z;
  int depth = 0;
  bool escaped = false;
  // Invert in the first circle that holds p and start over, until none does.
  for (; depth < maxIter; depth++) {
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
  if (!escaped) {
    // At maxIter: escaped only if p is in the tile (outside all four circles).
    vec2 q1 = p - C1, q2 = p - C2, q3 = p - C3, q4 = p - C4;
    escaped = !(dot(q1, q1) < R1 || dot(q2, q2) < R2 || dot(q3, q3) < R3 || dot(q4, q4) < R4);
  }
  outProbe = vec4(float(depth), p, escaped ? 1.0 : 0.0);
}
