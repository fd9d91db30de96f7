#version 300 es
precision highp float;
precision highp int;

// Frame uniforms (set by the runtime).
uniform vec2 u_resolution; // full image size in pixels
uniform vec2 u_pixelOffset; // offset of this framebuffer within the full image (tiled export)
uniform vec3 u_view; // view centre x, y and scale (world height of the image)
uniform vec2 u_jitter; // sub-pixel sample offset in [0,1)² (view.ts sampleOffset)
uniform float u_bgAlpha; // alpha of the background outside the clip disk (1; 0 for transparent export)
// Scene uniforms (values; changing them needs no recompile).
uniform vec4 u_el[4];
uniform int u_maxIterations;
out vec4 outProbe; // (depth, final.x, final.y, escaped)

float stripHeight(vec4 d0, vec2 p) {
  return (p.x - d0.x) * d0.z + (p.y - d0.y) * d0.w;
}

int foldCount(float k) {
  return max(int(min(abs(k), 1.0e9)), 1);
}

float stripIndex(vec4 d0, vec4 d1, vec2 p) {
  return floor(stripHeight(d0, p) / d1.x);
}

bool parallelMirrorsInside(vec2 p, vec4 d0, vec4 d1) {
  return stripIndex(d0, d1, p) != 0.0;
}

bool translationInside(vec2 p, vec4 d0, vec4 d1) {
  return stripIndex(d0, d1, p) != 0.0;
}

vec2 pixelToWorld(vec3 view, vec2 size, vec2 px, vec2 o) {
  return vec2(view.x + ((px.x + o.x - size.x / 2.0) / size.y) * view.z,
              view.y + ((px.y + o.y - size.y / 2.0) / size.y) * view.z);
}

bool runIis(inout vec2 p, inout float s, inout int depth) {
  vec4 el0 = u_el[0];
  vec4 el1 = u_el[1];
  vec4 el2 = u_el[2];
  vec4 el3 = u_el[3];
  int maxIter = u_maxIterations;
  for (; depth < maxIter; ++depth) {
#line 1 1
    { // parallel-mirrors
      vec4 d0 = el0;
      vec4 d1 = el1;
      float D = d1.x;
      float h = stripHeight(d0, p);
      float k = floor(h / D);
      if (k != 0.0) {
        float r = h - k * D;
        float target = mod(k, 2.0) == 0.0 ? r : D - r;
        p = vec2(p.x + (target - h) * d0.z, p.y + (target - h) * d0.w);
        depth += foldCount(k) - 1;
        continue;
      }
    }
#line 1 2
    { // translation
      vec4 d0 = el2;
      vec4 d1 = el3;
      float k = stripIndex(d0, d1, p);
      if (k != 0.0) {
        p = vec2(p.x - k * d1.y, p.y - k * d1.z);
        depth += foldCount(k) - 1;
        continue;
      }
    }
#line 75 0
    return true;
  }
  // depth ≥ maxIter: escaped only if no element holds p.
#line 1 1
  if (parallelMirrorsInside(p, el0, el1)) return false;
#line 1 2
  if (translationInside(p, el2, el3)) return false;
#line 83 0
  return true;
}

void main() {
  vec2 px = floor(gl_FragCoord.xy) + u_pixelOffset;
  vec2 w = pixelToWorld(u_view, u_resolution, px, u_jitter);
  vec2 p = w;
  float s = 1.0;
  int depth = 0;
  bool escaped = runIis(p, s, depth);
  outProbe = vec4(float(depth), p, escaped ? 1.0 : 0.0);
}
