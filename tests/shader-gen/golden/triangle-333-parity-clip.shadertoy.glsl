// Kleinflow: an Iterated Inversion System, generated from a node graph. Paste into Shadertoy.

bool reflectionInside(vec2 p, vec4 d0) {
  return (p.x - d0.x) * d0.z + (p.y - d0.y) * d0.w < 0.0;
}

vec3 finalColour(int depth, vec2 p) {
  return depth % 2 == 0 ? vec3(0.8480882574948618, 0.8073459089125288, 0.692071056865372) : vec3(0.01532520332062848, 0.0219809470798872, 0.046964200689122895);
}

vec3 shade(bool clipped, bool escaped, int depth, float edgePixels, vec2 p, float limitPixels, int seed) {
  if (clipped) return vec3(0.004896310081623859, 0.004896310081623859, 0.007194409291082934);
  if (!escaped) return vec3(0.0015479876160990713, 0.0015479876160990713, 0.0023219814241486067);
  vec3 base = finalColour(depth, p);
  return base;
}

vec2 pixelToWorld(vec3 view, vec2 size, vec2 px, vec2 o) {
  return vec2(view.x + ((px.x + o.x - size.x / 2.0) / size.y) * view.z,
              view.y + ((px.y + o.y - size.y / 2.0) / size.y) * view.z);
}

vec2 sampleOffset(int k) {
  if (k == 0) return vec2(0.5);
  return fract(vec2(0.5) + float(k) * vec2(0.7548776662466927, 0.5698402909980533));
}

float linearToSrgb(float c) {
  return c <= 0.0031308 ? 12.92 * c : 1.055 * pow(c, 1.0 / 2.4) - 0.055;
}

vec3 toSrgb(vec3 c) {
  return vec3(linearToSrgb(c.r), linearToSrgb(c.g), linearToSrgb(c.b));
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
  vec3 sum = vec3(0.0);
  for (int k = 0; k < 4; ++k) {
    vec2 w = pixelToWorld(view, iResolution.xy, px, sampleOffset(k));
    sum += shadeSample(w, view.z / iResolution.y, 1.0).rgb;
  }
  fragColor = vec4(toSrgb(sum / 4.0), 1.0);
}
