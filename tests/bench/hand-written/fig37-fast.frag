#version 300 es
// Hand-written sphere tracer for ONE scene, written for speed — the reference `npm run bench`
// measures the generated program against (tests/bench/trace3d.ts, and the first-draw bench
// tests/bench/first-draw3d.ts). The scene is the Fig. 37 example's geometry
// (examples/3d/fig37-indras-bubbles-mirror): Fig. 11's six inversion spheres of radius 0.7 at
// ±e_x, ±e_y, ±e_z around a seed ball of radius 0.29 at the origin, and eight bubbles of radius 0.6
// far outside the mirrors; 30 iterations, 200 march steps. Probe output only (hit, t, depth, seed):
// the mirror material changes the colour, not where rays hit. What a person writes for this one
// picture, not the generator's algorithm:
// - literals only, no arrays, no uniforms but the frame's; the nine seeds as one min of lengths;
// - one inversion per step, the pole of the composed map moved with the point, the bound once at
//   the end of the walk (docs/math-3d.md §8): the covers of the six balls (each cut down to the
//   content ball 0.67550·e_k, radius 0.55169), the nearest one seen through its mirror with its
//   reach (5.3774 for the x and y mirrors, 4.7233 and 4.6855 for +z and −z: the bubbles are farther
//   from the side mirrors);
// - the march inside the orbit's bounding ball (centre (0, 0, −0.05), radius 4.4398), DE scale 1,
//   hit on the seed-image distance.
// Constants are those prepareTrace3d gives, rounded outward.
precision highp float;
precision highp int;

uniform vec2 u_resolution;
uniform vec2 u_pixelOffset;
uniform vec2 u_jitter;
uniform vec3 u_cameraPosition;
uniform vec3 u_cameraTarget;
uniform float u_cameraFov;
out vec4 outProbe;

#define INVERT(c) { vec3 d = p - c; float d2 = dot(d, d); if (d2 < 0.49) { float k = 0.49 / max(d2, 1e-30); p = c + d * k; s *= k; vec3 e = pole - c; pole = c + e * (0.49 / max(dot(e, e), 1e-30)); depth += 1; continue; } }

// The nearest of the nine seeds: its signed distance, its index in `seed`.
#define SEED(c, r, k) { float dk = length(p - c) - r; if (dk < d) { d = dk; seed = k; } }
float seeds(vec3 p, out int seed) {
  float d = length(p) - 0.29;
  seed = 0;
  SEED(vec3(3.511, 1.454, 0.5), 0.6, 1)
  SEED(vec3(1.454, 3.511, -0.6), 0.6, 2)
  SEED(vec3(-1.454, 3.511, 0.5), 0.6, 3)
  SEED(vec3(-3.511, 1.454, -0.6), 0.6, 4)
  SEED(vec3(-3.511, -1.454, 0.5), 0.6, 5)
  SEED(vec3(-1.454, -3.511, -0.6), 0.6, 6)
  SEED(vec3(1.454, -3.511, 0.5), 0.6, 7)
  SEED(vec3(3.511, -1.454, -0.6), 0.6, 8)
  return d;
}

float cover(vec3 p, vec3 c) {
  return max(length(p - c) - 0.7, length(p - 0.6755 * c) - 0.55169);
}

// min(seeds, covers of every mirror but `skip`): the orbit outside mirror `skip`.
float coverBut(vec3 p, vec3 skip) {
  int unused;
  float d = max(0.0, seeds(p, unused));
  if (skip.x != 1.0) d = min(d, cover(p, vec3(1.0, 0.0, 0.0)));
  if (skip.x != -1.0) d = min(d, cover(p, vec3(-1.0, 0.0, 0.0)));
  if (skip.y != 1.0) d = min(d, cover(p, vec3(0.0, 1.0, 0.0)));
  if (skip.y != -1.0) d = min(d, cover(p, vec3(0.0, -1.0, 0.0)));
  if (skip.z != 1.0) d = min(d, cover(p, vec3(0.0, 0.0, 1.0)));
  if (skip.z != -1.0) d = min(d, cover(p, vec3(0.0, 0.0, -1.0)));
  return max(d, 0.0);
}

#define NEAREST(c) { float cj = cover(p, c); if (cj < d) { second = d; d = cj; near = c; } else second = min(second, cj); }

float walk(vec3 p, out float image, out int depth, out int seed) {
  float s = 1.0;
  vec3 pole = vec3(1e18, 0.0, 0.0);
  depth = 0;
  for (; depth < 30;) {
    INVERT(vec3(1.0, 0.0, 0.0))
    INVERT(vec3(-1.0, 0.0, 0.0))
    INVERT(vec3(0.0, 1.0, 0.0))
    INVERT(vec3(0.0, -1.0, 0.0))
    INVERT(vec3(0.0, 0.0, 1.0))
    INVERT(vec3(0.0, 0.0, -1.0))
    break;
  }
  float sd = seeds(p, seed);
  image = sd / s;
  float d = max(sd, 0.0);
  float second = 1e30;
  vec3 near = vec3(0.0);
  NEAREST(vec3(1.0, 0.0, 0.0))
  NEAREST(vec3(-1.0, 0.0, 0.0))
  NEAREST(vec3(0.0, 1.0, 0.0))
  NEAREST(vec3(0.0, -1.0, 0.0))
  NEAREST(vec3(0.0, 0.0, 1.0))
  NEAREST(vec3(0.0, 0.0, -1.0))
  if (near != vec3(0.0)) {
    vec3 e = p - near;
    vec3 q = near + e * (0.49 / max(dot(e, e), 1e-30));
    float far = length(q - near);
    float l = coverBut(q, near);
    float reach = near.z > 0.5 ? 4.7233 : near.z < -0.5 ? 4.6855 : 5.3774;
    d = min(second, max(d, 0.49 * l / (far * min(reach, far + l))));
  }
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
  vec3 oc = o - vec3(0.0, 0.0, -0.05);
  float b = dot(oc, dir);
  float disc = b * b - (dot(oc, oc) - 19.712); // 4.4398²
  if (disc <= 0.0) return;
  float h = sqrt(disc);
  float tEnd = -b + h;
  if (tEnd <= 0.0) return;
  float t = max(0.0, -b - h);
  float eps0 = 0.25 * a;
  for (int i = 0; i < 200; ++i) {
    float image;
    int depth;
    int seed;
    float de = walk(o + dir * t, image, depth, seed);
    float eps = eps0 * max(t, 4.44e-3);
    if (image < eps) {
      outProbe = vec4(1.0, t, float(depth), float(seed));
      return;
    }
    t += max(de, eps);
    if (t > tEnd) return;
  }
}
