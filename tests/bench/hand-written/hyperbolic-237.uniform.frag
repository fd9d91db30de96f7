#version 300 es
// The (2,3,7) triangle group of examples/hyperbolic-237 written by hand, with the scene's values as
// uniforms (what a drag changes): the reference for the generated uniform program. Same data as
// compile()'s u_el rows — mirror k: (q.x, q.y, n.x, n.y); circle: (c.x, c.y, r, r²) — copied into
// locals before the loop (SwiftShader reloads a uniform at every use inside a loop).
precision highp float;
precision highp int;

uniform vec2 u_resolution;
uniform vec2 u_pixelOffset;
uniform vec3 u_view;
uniform vec2 u_jitter;
uniform vec4 u_el[3];
uniform int u_maxIterations;
out vec4 outProbe;

void main() {
  vec2 Q1 = u_el[0].xy, N1 = u_el[0].zw;
  vec2 Q2 = u_el[1].xy, N2 = u_el[1].zw;
  vec2 C = u_el[2].xy;
  float R2 = u_el[2].w;
  int maxIter = u_maxIterations;
  vec2 px = floor(gl_FragCoord.xy) + u_pixelOffset;
  vec2 p = u_view.xy + (px + u_jitter - 0.5 * u_resolution) / u_resolution.y * u_view.z;
  int depth = 0;
  bool escaped = false;
  // Reflect or invert in the first mirror whose inside holds p and start over, until none does.
  for (; depth < maxIter; depth++) {
    float h = dot(p - Q1, N1);
    if (h < 0.0) {
      p -= 2.0 * h * N1;
      continue;
    }
    h = dot(p - Q2, N2);
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
  // At maxIter: escaped only if p is in the tile.
  if (!escaped) escaped = !(dot(p - Q1, N1) < 0.0 || dot(p - Q2, N2) < 0.0 || dot(p - C, p - C) < R2);
  outProbe = vec4(float(depth), p, escaped ? 1.0 : 0.0);
}
