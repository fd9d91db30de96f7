#version 300 es
// Hand-written volume renderer for ONE scene, written for speed — the reference `npm run bench`
// measures the generated volume program against (tests/bench/volume3d.ts). The scene is the Fig. 10
// example (examples/3d/fig10-volume-nesting-spheres): six inversion spheres of radius 0.7 at ±e_x,
// ±e_y, ±e_z, 30 iterations, 128 samples, density 0.6, growth 3, depths 1…5. Not a copy of the
// generator's program; what a person writes for this one picture:
// - literals only, no arrays, no uniforms but the frame's; the depth walk tests the six mirrors
//   inline and carries nothing but the point (no conformal factor, pole, seeds or bound);
// - the extinction per depth is a chain of literals (0.6·3^(k−1), k ≤ 5), σΔt once per sample;
// - the span is the mirrors' bounding sphere, |x| ≤ 1.7; early exit at T < 0.01.
// The per-pixel sample offset is the documented hash (docs/math-3d.md §11), so both sample the
// same points. Output: the volume probe (1 − T, τ, samples, 0).
precision highp float;
precision highp int;

uniform vec2 u_resolution;
uniform vec2 u_pixelOffset;
uniform vec2 u_jitter;
uniform vec3 u_cameraPosition;
uniform vec3 u_cameraTarget;
uniform float u_cameraFov;
out vec4 outProbe;

// Inversion in the sphere (c, 0.49) when p is inside it.
#define MIRROR(c) { vec3 d = p - c; float d2 = dot(d, d); if (d2 < 0.49) { p = c + d * (0.49 / max(d2, 1e-30)); depth++; continue; } }

int depthAt(vec3 p) {
  int depth = 0;
  while (depth < 30) {
    MIRROR(vec3(1.0, 0.0, 0.0))
    MIRROR(vec3(-1.0, 0.0, 0.0))
    MIRROR(vec3(0.0, 1.0, 0.0))
    MIRROR(vec3(0.0, -1.0, 0.0))
    MIRROR(vec3(0.0, 0.0, 1.0))
    MIRROR(vec3(0.0, 0.0, -1.0))
    break;
  }
  return depth;
}

uint mix32(uint x) {
  x = (x ^ (x >> 16u)) * 0x7feb352du;
  x = (x ^ (x >> 15u)) * 0x846ca68bu;
  return x ^ (x >> 16u);
}

void main() {
  vec2 px = floor(gl_FragCoord.xy) + u_pixelOffset;
  vec2 at = px + u_jitter;
  vec3 f = normalize(u_cameraTarget - u_cameraPosition);
  vec3 right = normalize(cross(f, vec3(0.0, 0.0, 1.0)));
  vec3 up = cross(right, f);
  vec2 uv = (at - 0.5 * u_resolution) * (2.0 * tan(radians(u_cameraFov) * 0.5) / u_resolution.y);
  vec3 d = normalize(f + uv.x * right + uv.y * up);
  vec3 o = u_cameraPosition;
  float b = dot(o, d);
  float disc = b * b - dot(o, o) + 2.89;
  outProbe = vec4(0.0);
  if (disc <= 0.0 || -b + sqrt(disc) <= 0.0) return;
  float h = sqrt(disc);
  float t0 = max(0.0, -b - h);
  float dt = (-b + h - t0) / 128.0;
  uvec2 q = uvec2(px);
  float j = float(mix32(q.x + mix32(q.y)) >> 8u) / 16777216.0;
  float T = 1.0;
  float tau = 0.0;
  for (int i = 0; i < 128; ++i) {
    int k = depthAt(o + d * (t0 + (float(i) + j) * dt));
    if (k == 0) continue;
    float sigma = (k == 1 ? 0.6 : k == 2 ? 1.8 : k == 3 ? 5.4 : k == 4 ? 16.2 : 48.6) * dt;
    tau += sigma;
    T *= exp(-sigma);
    if (T < 0.01) {
      outProbe = vec4(1.0 - T, tau, float(i + 1), 0.0);
      return;
    }
  }
  outProbe = vec4(1.0 - T, tau, 128.0, 0.0);
}
