/**
 * The limit sets of a Scene3d's quaternion groups as depth-sorted, shaded dots (docs/math-3d.md
 * "Quaternion Kleinian groups"): each limit point is projected by the tracer's own pinhole camera
 * (camera-3d.ts) and drawn as a small sphere impostor, lit by the scene's light, far dots first so
 * near ones cover them. The app's overlay canvas and the CPU PNG paint the same dots (painter
 * below), so the two pictures agree; the dots are drawn over the sphere-traced picture.
 */
import type { Lighting3d, Scene3d } from '../../nodes/core/scene-3d.ts';
import type { Color } from '../../nodes/core/values.ts';
import { dist3, dot3, normalize3, sub3, type Vec3 } from '../../nodes/geometry/space/vec3.ts';
import { linearToSrgb, toLinear } from '../srgb.ts';
import { type CameraBasis, cameraBasis, pixelAngle } from './camera-3d.ts';
import { limitSetSearch3d } from './limit-dfs-3d.ts';

export interface LimitDot3d {
  /** Pixel position, x from the left, y from the TOP (canvas and PNG order). */
  readonly x: number;
  readonly y: number;
  /** Radius, pixels. */
  readonly r: number;
  /** Distance along the view direction (sorting). */
  readonly depth: number;
  readonly color: Color;
}

export interface LimitDots3d {
  /** Far to near. */
  readonly dots: readonly LimitDot3d[];
  /** Why a limit set is partial, one line each, naming its node. */
  readonly notes: readonly { readonly nodeId: string; readonly text: string }[];
}

/**
 * Image position of point p: with rel = p − eye and depth z = rel·f,
 *   x = W/2 + (rel·right)/(z a),   y_from_bottom = H/2 + (rel·up)/(z a),   a = 2 tan(fov/2)/H,
 * the inverse of rayDirection (camera-3d.ts). Null behind (or at) the eye.
 */
export function projectPoint3d(
  b: CameraBasis,
  width: number,
  height: number,
  p: Vec3,
): { x: number; yUp: number; depth: number } | null {
  const rel = sub3(p, b.origin);
  const z = dot3(rel, b.forward);
  if (!(z > 1e-9)) return null;
  const a = pixelAngle(b, height);
  return {
    x: width / 2 + dot3(rel, b.right) / (z * a),
    yUp: height / 2 + dot3(rel, b.up) / (z * a),
    depth: z,
  };
}

/** The dots of every limit set of the scene for a width × height picture. */
export function limitDots3d(scene: Scene3d, width: number, height: number): LimitDots3d {
  const sets = scene.limitSets ?? [];
  if (sets.length === 0 || width <= 0 || height <= 0) return { dots: [], notes: [] };
  const b = cameraBasis(scene.camera);
  const reference = dist3(scene.camera.position, scene.camera.target);
  const dots: LimitDot3d[] = [];
  const notes: { nodeId: string; text: string }[] = [];
  for (const set of sets) {
    const found = limitSetSearch3d(set, scene.camera, width, height);
    if (found.capped) notes.push({ nodeId: set.nodeId, text: found.capped });
    for (const pt of found.points) {
      const q = projectPoint3d(b, width, height, pt.at);
      if (!q) continue;
      const r = Math.max(0.5, (set.dotPx * reference) / q.depth);
      if (q.x < -r || q.x > width + r || q.yUp < -r || q.yUp > height + r) continue;
      dots.push({ x: q.x, y: height - q.yUp, r, depth: q.depth, color: set.colors[pt.letter]! });
    }
  }
  dots.sort((p, q) => q.depth - p.depth);
  return { dots, notes };
}

/** The light in the camera's frame (x right, y up, z towards the viewer), unit. */
function lightInView(b: CameraBasis, lighting: Lighting3d): Vec3 {
  const l = normalize3(lighting.direction);
  return normalize3([dot3(l, b.right), dot3(l, b.up), -dot3(l, b.forward)]);
}

/**
 * Paints the dots over RGBA 8-bit sRGB `data` (row 0 at the top). A dot is a sphere seen from the
 * front: at offset (dx, dy)/r from its centre the normal is n = (dx, −dy, √(1 − dx² − dy²)), lit by
 *   colour·(ambient + diffuse·max(n·l, 0)) + specular·max(n·h, 0)^shininess   (h = (l + v)/|l + v|),
 * in linear light, with a one-pixel soft edge.
 */
export function paintLimitDots3d(
  scene: Scene3d,
  dots: readonly LimitDot3d[],
  width: number,
  height: number,
  data: Uint8ClampedArray,
): void {
  const l = lightInView(cameraBasis(scene.camera), scene.lighting);
  const h = normalize3([l[0], l[1], l[2] + 1]);
  const { ambient, diffuse, specular, shininess } = scene.lighting;
  for (const dot of dots) {
    const base = toLinear(dot.color);
    const x0 = Math.max(0, Math.floor(dot.x - dot.r - 1));
    const x1 = Math.min(width - 1, Math.ceil(dot.x + dot.r + 1));
    const y0 = Math.max(0, Math.floor(dot.y - dot.r - 1));
    const y1 = Math.min(height - 1, Math.ceil(dot.y + dot.r + 1));
    for (let y = y0; y <= y1; y++) {
      for (let x = x0; x <= x1; x++) {
        const dx = (x + 0.5 - dot.x) / dot.r;
        const dy = (y + 0.5 - dot.y) / dot.r;
        const d2 = dx * dx + dy * dy;
        const cover = Math.min(1, Math.max(0, (1 - Math.sqrt(d2)) * dot.r + 0.5));
        if (cover <= 0) continue;
        const nz = Math.sqrt(Math.max(0, 1 - d2));
        const nl = Math.max(0, dx * l[0] - dy * l[1] + nz * l[2]);
        const nh = Math.max(0, dx * h[0] - dy * h[1] + nz * h[2]);
        const spec = specular * nh ** shininess;
        const o = 4 * (y * width + x);
        // Over a transparent pixel (the app's overlay canvas) the edge fades by alpha alone.
        const clear = data[o + 3] === 0;
        for (let i = 0; i < 3; i++) {
          const lit = linearToSrgb(Math.min(1, base[i]! * (ambient + diffuse * nl) + spec));
          const under = clear ? lit : data[o + i]! / 255;
          data[o + i] = Math.round(255 * (lit * cover + under * (1 - cover)));
        }
        data[o + 3] = Math.max(data[o + 3]!, Math.round(255 * cover));
      }
    }
  }
}

/** Searches and paints the scene's limit sets over a finished render (the CLI's PNG); returns the notes. */
export function paintSceneLimitSets3d(
  scene: Scene3d,
  raster: { readonly width: number; readonly height: number; readonly data: Uint8ClampedArray },
): LimitDots3d['notes'] {
  const { dots, notes } = limitDots3d(scene, raster.width, raster.height);
  paintLimitDots3d(scene, dots, raster.width, raster.height, raster.data);
  return notes;
}
