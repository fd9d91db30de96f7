/**
 * A hand-written CPU volume renderer for ONE scene, written for speed — the reference
 * tests/bench/cpu-volume.ts times the generated CPU path (shader-gen/space/render-3d.ts) against.
 * The scene is the Fig. 10 example (examples/3d/fig10-volume-nesting-spheres): six inversion spheres
 * of radius 0.7 at ±e_x, ±e_y, ±e_z, 30 iterations, 128 samples, density 0.6, growth 3, depths 1…5,
 * the rainbow palette. Not a copy of the generated code; what a person writes for this picture:
 * literals, no arrays in the walk (the six mirrors tested inline on three numbers), the extinction
 * and the five colours as constants, span |x| ≤ 1.7, early exit at T < 0.01. The per-pixel sample
 * offset is the documented hash (docs/math-3d.md §11), so both sample the same points.
 */

const R2 = 0.49;

/** Depth of (x, y, z) under the six mirrors (at most 30 inversions). */
function depthAt(x: number, y: number, z: number): number {
  let depth = 0;
  while (depth < 30) {
    // The mirror on the axis of the largest coordinate is the only one that can hold the point.
    const ax = Math.abs(x);
    const ay = Math.abs(y);
    const az = Math.abs(z);
    let cx = 0;
    let cy = 0;
    let cz = 0;
    if (ax >= ay && ax >= az) cx = x > 0 ? 1 : -1;
    else if (ay >= az) cy = y > 0 ? 1 : -1;
    else cz = z > 0 ? 1 : -1;
    const dx = x - cx;
    const dy = y - cy;
    const dz = z - cz;
    const d2 = dx * dx + dy * dy + dz * dz;
    if (!(d2 < R2)) return depth;
    const k = R2 / Math.max(d2, 1e-300);
    x = cx + dx * k;
    y = cy + dy * k;
    z = cz + dz * k;
    depth++;
  }
  return depth;
}

const mix32 = (v: number): number => {
  let h = Math.imul(v ^ (v >>> 16), 0x7feb352d) >>> 0;
  h = Math.imul(h ^ (h >>> 15), 0x846ca68b) >>> 0;
  return (h ^ (h >>> 16)) >>> 0;
};

const lin = (c: number) => (c <= 0.04045 ? c / 12.92 : ((c + 0.055) / 1.055) ** 2.4);
const enc = (c: number) => (c <= 0.0031308 ? 12.92 * c : 1.055 * c ** (1 / 2.4) - 0.055);
/** Rainbow palette 0.5 + 0.5·cos(2π(u + d)) at u = k/5, k = 1…5, linear light. */
const COLOURS = [1, 2, 3, 4, 5].map((k) =>
  [0, 0.33, 0.67].map((d) => lin(Math.min(1, Math.max(0, 0.5 + 0.5 * Math.cos(2 * Math.PI * (k / 5 + d)))))),
);
const SIGMA = [0, 0.6, 1.8, 5.4, 16.2, 48.6];

/** RGBA bytes, row 0 at the top, 1 sample per pixel at the centre, over the background `bg` (sRGB). */
export function renderFig10Volume(
  width: number,
  height: number,
  camera: { position: readonly number[]; target: readonly number[]; fovDeg: number },
  bg: readonly number[],
): Uint8ClampedArray {
  const out = new Uint8ClampedArray(width * height * 4);
  const [ox, oy, oz] = camera.position as [number, number, number];
  let fx = camera.target[0]! - ox;
  let fy = camera.target[1]! - oy;
  let fz = camera.target[2]! - oz;
  const fl = Math.hypot(fx, fy, fz);
  fx /= fl;
  fy /= fl;
  fz /= fl;
  // right = f × z, up = right × f
  const rl = Math.hypot(fy, fx);
  const rx = fy / rl;
  const ry = -fx / rl;
  const ux = ry * fz;
  const uy = -rx * fz;
  const uz = rx * fy - ry * fx;
  const a = (2 * Math.tan((camera.fovDeg * Math.PI) / 360)) / height;
  const bgl = bg.map(lin);
  for (let row = 0; row < height; row++) {
    const py = height - 1 - row;
    for (let px = 0; px < width; px++) {
      const u = (px + 0.5 - width / 2) * a;
      const v = (py + 0.5 - height / 2) * a;
      let dx = fx + u * rx + v * ux;
      let dy = fy + u * ry + v * uy;
      let dz = fz + v * uz;
      const dl = Math.hypot(dx, dy, dz);
      dx /= dl;
      dy /= dl;
      dz /= dl;
      let r = 0;
      let g = 0;
      let b = 0;
      let T = 1;
      const bb = ox * dx + oy * dy + oz * dz;
      const disc = bb * bb - (ox * ox + oy * oy + oz * oz - 2.89);
      if (disc > 0 && -bb + Math.sqrt(disc) > 0) {
        const h = Math.sqrt(disc);
        const t0 = Math.max(0, -bb - h);
        const dt = (-bb + h - t0) / 128;
        const j = (mix32((px + mix32(py)) >>> 0) >>> 8) / 16777216;
        for (let i = 0; i < 128; i++) {
          const t = t0 + (i + j) * dt;
          const k = Math.min(5, depthAt(ox + dx * t, oy + dy * t, oz + dz * t));
          if (k === 0) continue;
          const alpha = 1 - Math.exp(-SIGMA[k]! * dt);
          const c = COLOURS[k - 1]!;
          r += T * alpha * c[0]!;
          g += T * alpha * c[1]!;
          b += T * alpha * c[2]!;
          T *= 1 - alpha;
          if (T < 0.01) break;
        }
      }
      const o = 4 * (row * width + px);
      out[o] = Math.round(255 * enc(Math.min(1, r + T * bgl[0]!)));
      out[o + 1] = Math.round(255 * enc(Math.min(1, g + T * bgl[1]!)));
      out[o + 2] = Math.round(255 * enc(Math.min(1, b + T * bgl[2]!)));
      out[o + 3] = 255;
    }
  }
  return out;
}
