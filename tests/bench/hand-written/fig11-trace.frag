#version 300 es
// Hand-written sphere tracer for ONE scene, tests/shader-gen/space/scenes-3d.ts FIG11 (six
// inversion spheres of radius 1.25 at ±2·e_k, one seed sphere of radius 0.7 at the origin), with
// the same algorithm as the generated program (docs/math-3d.md §8, §9) written the way a person
// would: constant arrays and loops, no unrolling. Probe output (hit, t, depth, seed) like
// compile3d's probe variant. The content balls and reaches are the values prepareTrace3d gives
// for this scene, rounded up. Used by tests/bench/trace3d.ts (speed) and tests/parity (same picture).
precision highp float;
precision highp int;

uniform vec2 u_resolution;
uniform vec2 u_pixelOffset;
uniform vec2 u_jitter;
uniform vec3 u_cameraPosition;
uniform vec3 u_cameraTarget;
uniform float u_cameraFov;
out vec4 outProbe;

const int N = 6;
const vec3 CENTRE[6] = vec3[6](vec3(2.0, 0.0, 0.0), vec3(-2.0, 0.0, 0.0), vec3(0.0, 2.0, 0.0),
                               vec3(0.0, -2.0, 0.0), vec3(0.0, 0.0, 2.0), vec3(0.0, 0.0, -2.0));
const float R = 1.25;
const float R2 = 1.5625;
// Content ball i: centre 1.34614·(centre i)/2, radius 0.5482; reach M_i.
const float HULL_AT = 0.67307;
const float HULL_R = 0.5482;
const float REACH = 3.8943;
const float SEED_R = 0.7;
const int MAX_ITER = 30;
const int MARCH = 200;
const float DE_SCALE = 0.9;
const float BOUND_R = 3.25;
const float FAR = 3.0e38;

float cover(vec3 p, int skip) {
  float d = max(0.0, length(p) - SEED_R);
  for (int j = 0; j < N; ++j) {
    if (j == skip) continue;
    float ball = max(0.0, length(p - CENTRE[j]) - R);
    float hull = max(0.0, length(p - CENTRE[j] * HULL_AT) - HULL_R);
    d = min(d, max(ball, hull));
  }
  return d;
}

// The safe distance bound and, in info, (seed-image distance, depth, seed, factor).
float walk(vec3 p, out vec4 info) {
  vec4 stack[64];
  int top = 0;
  float s = 1.0;
  int depth = 0;
  while (depth < MAX_ITER && top <= 63) {
    int hit = -1;
    for (int i = 0; i < N; ++i) {
      vec3 d = p - CENTRE[i];
      if (dot(d, d) < R2) {
        hit = i;
        break;
      }
    }
    if (hit < 0) break;
    vec3 d = p - CENTRE[hit];
    float d2 = max(dot(d, d), 1e-30);
    float k = R2 / d2;
    stack[top] = vec4(cover(p, hit), R2, R2 * inversesqrt(d2), REACH);
    top += 1;
    p = CENTRE[hit] + d * k;
    s *= k;
    depth += 1;
  }
  info = vec4((length(p) - SEED_R) / s, float(depth), 0.0, s);
  float de = cover(p, -1);
  for (int k = top - 1; k >= 0; --k) {
    vec4 r = stack[k];
    de = min(r.x, r.y * (de / (r.z * min(r.w, r.z + de))));
  }
  return de;
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
  float b = dot(o, dir);
  float disc = b * b - (dot(o, o) - BOUND_R * BOUND_R);
  if (disc <= 0.0 || -b + sqrt(disc) <= 0.0) return;
  float t = max(0.0, -b - sqrt(disc));
  float tEnd = -b + sqrt(disc);
  for (int i = 0; i < MARCH; ++i) {
    vec4 info;
    float de = walk(o + dir * t, info);
    float eps = 0.25 * a * max(t, 1e-3 * BOUND_R);
    if (info.x < eps) {
      outProbe = vec4(1.0, t, info.y, 0.0);
      return;
    }
    t += max(DE_SCALE * de, eps);
    if (t > tEnd) return;
  }
}
