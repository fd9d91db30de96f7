#version 300 es
// Hand-written sphere tracer for ONE scene, written for speed — the reference `npm run bench`
// measures the generated program against (tests/bench/trace3d.ts). The scene is the Fig. 11 example
// (examples/3d/fig11-sphere-inversion-fractal): six inversion spheres of radius 0.7 at ±e_x, ±e_y,
// ±e_z, one seed sphere of radius 0.29 at the origin, 30 iterations, 200 march steps. It is NOT a
// copy of the generator's algorithm; what a person writes for this one picture:
// - literals only, no arrays, no uniforms but the frame's;
// - the walk applies one inversion per step and moves the pole of the composed map with the point
//   (docs/math-3d.md §8: one triangle inequality through the whole map, no per-step bound);
// - the bound is evaluated once, at the end of the walk: the covers of the six balls (each the
//   mirror ball cut down to the ball that holds the orbit inside it), the nearest one seen through
//   its mirror;
// - the march runs inside the tight bounding sphere of the orbit (radius 0.977, the orbit's pieces,
//   not the mirror balls' 1.7) at DE scale 1 and hits on the seed-image distance.
// Constants: the content ball of mirror ±e_k is centred at ±0.67549·e_k with radius 0.55168; every
// orbit point outside a mirror ball lies within 2.2272 of its centre (values prepareTrace3d gives,
// rounded outward: smaller content radius would not be safe, so they are rounded up).
precision highp float;
precision highp int;

uniform vec2 u_resolution;
uniform vec2 u_pixelOffset;
uniform vec2 u_jitter;
uniform vec3 u_cameraPosition;
uniform vec3 u_cameraTarget;
uniform float u_cameraFov;
out vec4 outProbe;

// One inversion in the sphere (c, 0.49) when p is inside it: moves p and the pole, scales s.
#define INVERT(c) { vec3 d = p - c; float d2 = dot(d, d); if (d2 < 0.49) { float k = 0.49 / max(d2, 1e-30); p = c + d * k; s *= k; vec3 e = pole - c; pole = c + e * (0.49 / max(dot(e, e), 1e-30)); depth += 1; continue; } }

// Distance to the orbit inside mirror c: the mirror ball and its content ball.
float cover(vec3 p, vec3 c) {
  return max(length(p - c) - 0.7, length(p - 0.67549 * c) - 0.55169);
}

// min(seed, covers of every mirror but `skip`) — the orbit outside mirror `skip`.
float coverBut(vec3 p, vec3 skip) {
  float d = max(0.0, length(p) - 0.29);
  if (skip.x != 1.0) d = min(d, cover(p, vec3(1.0, 0.0, 0.0)));
  if (skip.x != -1.0) d = min(d, cover(p, vec3(-1.0, 0.0, 0.0)));
  if (skip.y != 1.0) d = min(d, cover(p, vec3(0.0, 1.0, 0.0)));
  if (skip.y != -1.0) d = min(d, cover(p, vec3(0.0, -1.0, 0.0)));
  if (skip.z != 1.0) d = min(d, cover(p, vec3(0.0, 0.0, 1.0)));
  if (skip.z != -1.0) d = min(d, cover(p, vec3(0.0, 0.0, -1.0)));
  return max(d, 0.0);
}

#define NEAREST(c) { float cj = cover(p, c); if (cj < d) { second = d; d = cj; near = c; } else second = min(second, cj); }

// The safe bound at the start point; `image` gets the seed-image distance, `depth` the steps.
float walk(vec3 p, out float image, out int depth) {
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
  float seed = length(p) - 0.29;
  image = seed / s;
  float d = max(seed, 0.0);
  float second = 1e30;
  vec3 near = vec3(0.0);
  NEAREST(vec3(1.0, 0.0, 0.0))
  NEAREST(vec3(-1.0, 0.0, 0.0))
  NEAREST(vec3(0.0, 1.0, 0.0))
  NEAREST(vec3(0.0, -1.0, 0.0))
  NEAREST(vec3(0.0, 0.0, 1.0))
  NEAREST(vec3(0.0, 0.0, -1.0))
  if (near != vec3(0.0)) {
    // The orbit inside the nearest mirror is the mirror image of the orbit outside it.
    vec3 e = p - near;
    vec3 q = near + e * (0.49 / max(dot(e, e), 1e-30));
    float far = length(q - near);
    float l = coverBut(q, near);
    d = min(second, max(d, 0.49 * l / (far * min(2.2272, far + l))));
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
  float b = dot(o, dir);
  float disc = b * b - (dot(o, o) - 0.9546); // bounding sphere: centre 0, radius 0.97704
  if (disc <= 0.0) return;
  float h = sqrt(disc);
  float tEnd = -b + h;
  if (tEnd <= 0.0) return;
  float t = max(0.0, -b - h);
  float eps0 = 0.25 * a;
  for (int i = 0; i < 200; ++i) {
    float image;
    int depth;
    float de = walk(o + dir * t, image, depth);
    float eps = eps0 * max(t, 9.77e-4);
    if (image < eps) {
      outProbe = vec4(1.0, t, float(depth), 0.0);
      return;
    }
    t += max(de, eps);
    if (t > tEnd) return;
  }
}
