// Kleinflow: an Iterated Inversion System, generated from a node graph. Paste into Shadertoy.

bool reflectionInside(vec2 p, vec4 d0) {
  return (p.x - d0.x) * d0.z + (p.y - d0.y) * d0.w < 0.0;
}

vec3 finalColour(int depth, vec2 p) {
  return depth % 2 == 0 ? vec3(0.93, 0.91, 0.85) : vec3(0.13, 0.16, 0.24);
}

vec3 shade(bool clipped, bool escaped, int depth, float edgePixels, vec2 p, float limitPixels, int seed) {
  if (clipped) return vec3(0.06, 0.06, 0.08);
  if (!escaped) return vec3(0.02, 0.02, 0.03);
  vec3 base = finalColour(depth, p);
  return base;
}

vec2 pixelToWorld(vec3 view, vec2 size, vec2 px, vec2 o) {
  return vec2(view.x + ((px.x + o.x - size.x / 2.0) / size.y) * view.z,
              view.y + ((px.y + o.y - size.y / 2.0) / size.y) * view.z);
}

bool runIis(inout vec2 p, inout float s, inout int depth) {
  for (; depth < 100; ++depth) {
    { // reflection
      vec4 d0 = vec4(0.0, 0.0, 0.0, 1.0);
      float h = (p.x - d0.x) * d0.z + (p.y - d0.y) * d0.w;
      if (!(h >= 0.0)) {
        h *= 2.0;
        p = vec2(p.x - h * d0.z, p.y - h * d0.w);
        continue;
      }
    }
    { // reflection
      vec4 d0 = vec4(0.0, 0.0, 0.8660254037844386, -0.5000000000000001);
      float h = (p.x - d0.x) * d0.z + (p.y - d0.y) * d0.w;
      if (!(h >= 0.0)) {
        h *= 2.0;
        p = vec2(p.x - h * d0.z, p.y - h * d0.w);
        continue;
      }
    }
    { // reflection
      vec4 d0 = vec4(1.0, 0.0, -0.8660254037844386, -0.5000000000000001);
      float h = (p.x - d0.x) * d0.z + (p.y - d0.y) * d0.w;
      if (!(h >= 0.0)) {
        h *= 2.0;
        p = vec2(p.x - h * d0.z, p.y - h * d0.w);
        continue;
      }
    }
    return true;
  }
  // depth ≥ maxIter: escaped only if no element holds p.
  if (reflectionInside(p, vec4(0.0, 0.0, 0.0, 1.0))) return false;
  if (reflectionInside(p, vec4(0.0, 0.0, 0.8660254037844386, -0.5000000000000001))) return false;
  if (reflectionInside(p, vec4(1.0, 0.0, -0.8660254037844386, -0.5000000000000001))) return false;
  return true;
}

vec4 shadeSample(vec2 w, float pixelWorld, float bgAlpha) {
  vec3 clip = vec3(0.5, 0.3, 1.5);
  float cx = w.x - clip.x;
  float cy = w.y - clip.y;
  bool clipped = cx * cx + cy * cy > clip.z * clip.z;
  vec2 p = w;
  float s = 1.0;
  int depth = 0;
  int seed = -1;
  bool escaped = clipped ? false : runIis(p, s, depth);
  float edgePixels = 3.0e38;
  float limitPixels = 3.0e38;
  return vec4(shade(clipped, escaped, depth, edgePixels, p, limitPixels, seed), clipped ? bgAlpha : 1.0);
}

void mainImage(out vec4 fragColor, in vec2 fragCoord) {
  vec3 view = vec3(0.0, 0.0, 3.0);
  vec2 px = floor(fragCoord);
  vec2 w = pixelToWorld(view, iResolution.xy, px, vec2(0.5));
  fragColor = vec4(shadeSample(w, view.z / iResolution.y, 1.0).rgb, 1.0);
}
