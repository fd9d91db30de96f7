#version 300 es
// Hand-written sphere tracer for ONE scene, written for speed — the reference `npm run bench`
// measures the generated program against (tests/bench/trace3d.ts). The scene is the Fig. 26
// example (examples/3d/fig26-quasi-sphere): the finite cube-type sphairahedron, six inversion
// spheres meeting at angles π/n (their balls overlap), the seed ball below the floor clipped by
// them, 200 iterations, 1000 march steps. What a person writes for this one picture:
// - named constants, no arrays, no uniforms but the frame's; one inversion per IIS step, the pole of
//   the composed map moved with the point (docs/math-3d.md §8);
// - the bound evaluated once, at the end of the walk: the seed and the six covers (the first three
//   mirror balls cut down to the balls that hold the orbit inside them), the nearest cover seen
//   through its mirror (overlapping faces need it: without it the covers hug the faces);
// - the march inside the orbit's bounding sphere at DE scale 1, hit on the seed-image distance.
// Values: the sphairahedron node's, and the content balls and reaches that prepareTrace3d gives,
// radii and reaches rounded up (a smaller one would not be safe).
precision highp float;
precision highp int;

uniform vec2 u_resolution;
uniform vec2 u_pixelOffset;
uniform vec2 u_jitter;
uniform vec3 u_cameraPosition;
uniform vec3 u_cameraTarget;
uniform float u_cameraFov;
out vec4 outProbe;

const vec3 C0 = vec3(-2.25, 0.0, 1.6);
const vec3 C1 = vec3(1.125, -1.94855716, 1.6);
const vec3 C2 = vec3(1.125, 1.94855716, 1.6);
const vec3 C3 = vec3(0.446083172, 0.0, 0.207350097);
const vec3 C4 = vec3(-0.299003322, 0.517888946, -0.129947793);
const vec3 C5 = vec3(-0.17866005, -0.309448283, 0.297270471);
const float R0 = 2.25;
const float R3 = 0.424323017;
const float R4 = 0.683436165;
const float R5 = 0.387096774;
const float Q0 = 5.0625; // radius², the same for the three big faces
const float Q3 = 0.180050023;
const float Q4 = 0.467084992;
const float Q5 = 0.149843913;
const vec3 H0 = vec3(-0.562500109, 0.000359850395, 1.60000071);
const vec3 H1 = vec3(0.281149218, -0.487197476, 1.60000063);
const vec3 H2 = vec3(0.281555095, 0.486963143, 1.60000072);
const float HR0 = 2.0996389;
const float HR1 = 2.0993955;
const float HR2 = 2.0996314;
const vec3 SEED = vec3(0.0, 0.0, 0.925746163);
const float SEED_R = 0.674253837;

#define INVERT(c, q) { vec3 d = p - c; float d2 = dot(d, d); if (d2 < q) { float k = q / max(d2, 1e-30); p = c + d * k; s *= k; vec3 e = pole - c; pole = c + e * (q / max(dot(e, e), 1e-30)); depth += 1; continue; } }

float ball(vec3 p, vec3 c, float r) { return max(0.0, length(p - c) - r); }
float cover0(vec3 p) { return max(ball(p, C0, R0), ball(p, H0, HR0)); }
float cover1(vec3 p) { return max(ball(p, C1, R0), ball(p, H1, HR1)); }
float cover2(vec3 p) { return max(ball(p, C2, R0), ball(p, H2, HR2)); }
float seedDist(vec3 p) { return length(p - SEED) - SEED_R; }

// min(seed, covers but `skip`): the orbit outside face `skip`.
float coverBut(vec3 p, int skip) {
  float d = max(0.0, seedDist(p));
  if (skip != 0) d = min(d, cover0(p));
  if (skip != 1) d = min(d, cover1(p));
  if (skip != 2) d = min(d, cover2(p));
  if (skip != 3) d = min(d, ball(p, C3, R3));
  if (skip != 4) d = min(d, ball(p, C4, R4));
  if (skip != 5) d = min(d, ball(p, C5, R5));
  return d;
}

// r²·L/(F·min(M, F + L)): the orbit inside face (c, q) seen from p through the face.
float mirrored(vec3 p, vec3 c, float q, float reach, int j) {
  vec3 e = p - c;
  vec3 m = c + e * (q / max(dot(e, e), 1e-30));
  float far = length(m - c);
  float l = coverBut(m, j);
  return q * l / (far * min(reach, far + l));
}

#define NEAREST(cj, j) { float c_ = cj; if (c_ < d) { second = d; d = c_; near = j; } else second = min(second, c_); }

float walk(vec3 p, out float image, out int depth) {
  float s = 1.0;
  vec3 pole = vec3(1e18, 0.0, 0.0);
  depth = 0;
  for (; depth < 200;) {
    INVERT(C0, Q0)
    INVERT(C1, Q0)
    INVERT(C2, Q0)
    INVERT(C3, Q3)
    INVERT(C4, Q4)
    INVERT(C5, Q5)
    break;
  }
  float seed = seedDist(p);
  image = seed / s;
  float d = max(seed, 0.0);
  float second = 1e30;
  int near = -1;
  NEAREST(cover0(p), 0)
  NEAREST(cover1(p), 1)
  NEAREST(cover2(p), 2)
  NEAREST(ball(p, C3, R3), 3)
  NEAREST(ball(p, C4, R4), 4)
  NEAREST(ball(p, C5, R5), 5)
  if (near == 0) d = max(d, mirrored(p, C0, Q0, 4.67760, 0));
  else if (near == 1) d = max(d, mirrored(p, C1, Q0, 4.67761, 1));
  else if (near == 2) d = max(d, mirrored(p, C2, Q0, 4.67719, 2));
  else if (near == 3) d = max(d, mirrored(p, C3, Q3, 3.81915, 3));
  else if (near == 4) d = max(d, mirrored(p, C4, Q4, 4.18255, 4));
  else if (near == 5) d = max(d, mirrored(p, C5, Q5, 3.69437, 5));
  d = min(d, second);
  return d / (s * (1.0 + d / length(p - pole)));
}

void main() {
  vec2 at = floor(gl_FragCoord.xy) + u_pixelOffset + u_jitter;
  vec3 f = normalize(u_cameraTarget - u_cameraPosition);
  vec3 right = normalize(cross(f, vec3(0.0, 0.0, 1.0)));
  vec3 up = cross(right, f);
  float a = 2.0 * tan(radians(u_cameraFov) * 0.5) / u_resolution.y;
  vec2 uv = (at - u_resolution * 0.5) * a;
  vec3 o = u_cameraPosition;
  vec3 dir = normalize(f + uv.x * right + uv.y * up);
  outProbe = vec4(0.0, 0.0, 0.0, -1.0);
  vec3 oc = o - vec3(0.00483029, 0.000686297, 1.34961003); // bounding sphere, radius 2.28048
  float b = dot(oc, dir);
  float disc = b * b - (dot(oc, oc) - 5.20058906);
  if (disc <= 0.0) return;
  float h = sqrt(disc);
  float tEnd = -b + h;
  if (tEnd <= 0.0) return;
  float t = max(0.0, -b - h);
  float eps0 = 0.25 * a;
  for (int i = 0; i < 1000; ++i) {
    float image;
    int depth;
    float de = walk(o + dir * t, image, depth);
    float eps = eps0 * max(t, 2.28e-3);
    if (image < eps) {
      outProbe = vec4(1.0, t, float(depth), 0.0);
      return;
    }
    t += max(de, eps);
    if (t > tEnd) return;
  }
}
