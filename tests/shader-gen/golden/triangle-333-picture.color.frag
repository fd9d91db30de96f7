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
uniform vec3 u_background;
uniform vec4 u_el[3];
uniform vec3 u_limitColor;
uniform int u_maxIterations;
uniform vec4 u_picture;
uniform vec2 u_pictureRot;
// Pictures (textures; the runtime binds texture unit N to u_imageN).
uniform sampler2D u_image0;
out vec4 outColor; // linear RGB; alpha u_bgAlpha on the background

bool reflectionInside(vec2 p, vec4 d0) {
  return (p.x - d0.x) * d0.z + (p.y - d0.y) * d0.w < 0.0;
}

vec2 placeUv(vec4 rect, vec2 rot, vec2 p) {
  float dx = p.x - rect.x;
  float dy = p.y - rect.y;
  float lx = rot.x * dx + rot.y * dy;
  float ly = -rot.y * dx + rot.x * dy;
  return vec2(lx / rect.z + 0.5, 0.5 - ly / rect.w);
}

vec3 finalColour(int depth, vec2 p) {
  return textureLod(u_image0, placeUv(u_picture, u_pictureRot, p), 0.0).rgb;
}

vec3 shade(bool clipped, bool escaped, int depth, float edgePixels, vec2 p, float limitPixels, int seed) {
  if (clipped) return u_background;
  if (!escaped) return u_limitColor;
  vec3 base = finalColour(depth, p);
  return base;
}

vec2 pixelToWorld(vec3 view, vec2 size, vec2 px, vec2 o) {
  return vec2(view.x + ((px.x + o.x - size.x / 2.0) / size.y) * view.z,
              view.y + ((px.y + o.y - size.y / 2.0) / size.y) * view.z);
}

bool runIis(inout vec2 p, inout float s, inout int depth) {
  vec4 el0 = u_el[0];
  vec4 el1 = u_el[1];
  vec4 el2 = u_el[2];
  int maxIter = u_maxIterations;
  for (; depth < maxIter; ++depth) {
#line 1 1
    { // reflection
      vec4 d0 = el0;
      float h = (p.x - d0.x) * d0.z + (p.y - d0.y) * d0.w;
      if (!(h >= 0.0)) {
        h *= 2.0;
        p = vec2(p.x - h * d0.z, p.y - h * d0.w);
        continue;
      }
    }
#line 1 2
    { // reflection
      vec4 d0 = el1;
      float h = (p.x - d0.x) * d0.z + (p.y - d0.y) * d0.w;
      if (!(h >= 0.0)) {
        h *= 2.0;
        p = vec2(p.x - h * d0.z, p.y - h * d0.w);
        continue;
      }
    }
#line 1 3
    { // reflection
      vec4 d0 = el2;
      float h = (p.x - d0.x) * d0.z + (p.y - d0.y) * d0.w;
      if (!(h >= 0.0)) {
        h *= 2.0;
        p = vec2(p.x - h * d0.z, p.y - h * d0.w);
        continue;
      }
    }
#line 87 0
    return true;
  }
  // depth ≥ maxIter: escaped only if no element holds p.
#line 1 1
  if (reflectionInside(p, el0)) return false;
#line 1 2
  if (reflectionInside(p, el1)) return false;
#line 1 3
  if (reflectionInside(p, el2)) return false;
#line 97 0
  return true;
}

vec4 shadeSample(vec2 w, float pixelWorld, float bgAlpha) {
  bool clipped = false;
  vec2 p = w;
  float s = 1.0;
  int depth = 0;
  int seed = -1;
  bool escaped = clipped ? false : runIis(p, s, depth);
  float edgePixels = 3.0e38;
  float limitPixels = 3.0e38;
  return vec4(shade(clipped, escaped, depth, edgePixels, p, limitPixels, seed), clipped ? bgAlpha : 1.0);
}

void main() {
  vec2 px = floor(gl_FragCoord.xy) + u_pixelOffset;
  vec2 w = pixelToWorld(u_view, u_resolution, px, u_jitter);
  outColor = shadeSample(w, u_view.z / u_resolution.y, u_bgAlpha);
}
