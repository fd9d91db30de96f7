/**
 * A linked program with its uniform locations (looked up once, when it is linked) and the uploads:
 * the scene's uniforms from the CompiledProgram, and the per-frame uniforms the runtime sets.
 */
import type { Camera3d } from '../../nodes/core/scene-3d.ts';
import type { View } from '../../nodes/core/view.ts';
import { FRAME_UNIFORMS, type UniformEntry } from '../../shader-gen/compile.ts';
import { cameraUniforms } from '../../shader-gen/space/compile-3d.ts';

type FrameUniform = (typeof FRAME_UNIFORMS)[number]['name'];

export interface GpuProgram {
  readonly program: WebGLProgram;
  /** Location of each uniform by name; null when the shader declares it but does not use it. */
  readonly locations: ReadonlyMap<string, WebGLUniformLocation | null>;
  /** The entries uploaded last: a program shared by two renders re-uploads only on a change of owner. */
  uploaded: readonly UniformEntry[] | null;
}

export function locateUniforms(
  gl: WebGL2RenderingContext,
  program: WebGLProgram,
  sceneUniforms: readonly UniformEntry[],
): GpuProgram {
  const locations = new Map<string, WebGLUniformLocation | null>();
  for (const name of [...FRAME_UNIFORMS.map((u) => u.name), ...sceneUniforms.map((u) => u.name)]) {
    locations.set(name, gl.getUniformLocation(program, name));
  }
  return { program, locations, uploaded: null };
}

/**
 * Dev and test builds throw on a non-finite value (a NaN uniform paints garbage silently);
 * production builds skip that uniform and keep its previous value. Vite sets PROD in builds.
 */
const STRICT = (import.meta as { env?: { PROD?: boolean } }).env?.PROD !== true;

function finite(u: UniformEntry): boolean {
  for (const v of u.value) if (!Number.isFinite(v)) return false;
  return true;
}

/** Sets one uniform of the program in use (a name it was not linked with is looked up once). */
function setUniform(gl: WebGL2RenderingContext, gp: GpuProgram, u: UniformEntry): void {
  let loc = gp.locations.get(u.name);
  if (loc === undefined) {
    // A uniform this program was not linked with (same structure, new name): look it up once.
    loc = gl.getUniformLocation(gp.program, u.name);
    (gp.locations as Map<string, WebGLUniformLocation | null>).set(u.name, loc);
  }
  if (loc === null) return;
  const v = u.value;
  switch (u.type) {
    case 'float':
      gl.uniform1f(loc, v[0]);
      break;
    case 'int':
      gl.uniform1i(loc, v[0]);
      break;
    case 'vec2':
      gl.uniform2f(loc, v[0], v[1]);
      break;
    case 'vec3':
      gl.uniform3f(loc, v[0], v[1], v[2]);
      break;
    case 'vec4':
      gl.uniform4f(loc, v[0], v[1], v[2], v[3]);
      break;
    case 'vec4[]':
      gl.uniform4fv(loc, v);
      break;
    case 'float[]':
      gl.uniform1fv(loc, v);
      break;
  }
}

/** Uploads the scene's uniforms; the program must be in use. Never uploads NaN or ∞. */
export function uploadUniforms(
  gl: WebGL2RenderingContext,
  gp: GpuProgram,
  entries: readonly UniformEntry[],
): void {
  for (const u of entries) {
    if (!finite(u)) {
      const message = `uniform ${u.name} has a non-finite value [${u.value.join(', ')}]`;
      if (STRICT) throw new Error(message);
      console.warn(`[kleinflow] ${message}; not uploaded`);
      continue;
    }
    setUniform(gl, gp, u);
  }
  gp.uploaded = entries;
}

/** Where one draw sits in the whole image and which sub-pixel sample it takes. */
export interface FrameParams {
  /** Size of the whole image in pixels (the canvas, or the exported picture). */
  readonly width: number;
  readonly height: number;
  /** Offset of the framebuffer being drawn within the whole image (tiles), bottom-left origin. */
  readonly offsetX: number;
  readonly offsetY: number;
  readonly view: View;
  /** The 3D view's camera (a 3D program's frame uniforms); absent for a 2D program. */
  readonly camera?: Camera3d;
  /** Sub-pixel offset in [0,1)² (shader-gen/view.ts sampleOffset). */
  readonly jitter: readonly [number, number];
  /** 1 normally; 0 makes the background transparent (export). */
  readonly bgAlpha: number;
}

export function setFrameUniforms(gl: WebGL2RenderingContext, gp: GpuProgram, f: FrameParams): void {
  const at = (name: FrameUniform) => gp.locations.get(name) ?? null;
  const { center, scale } = f.view;
  if (![center[0], center[1], scale, f.width, f.height].every(Number.isFinite)) {
    throw new Error(`non-finite frame uniforms: view ${center} × ${scale}, size ${f.width}×${f.height}`);
  }
  gl.uniform2f(at('u_resolution'), f.width, f.height);
  gl.uniform2f(at('u_pixelOffset'), f.offsetX, f.offsetY);
  gl.uniform3f(at('u_view'), center[0], center[1], scale);
  gl.uniform2f(at('u_jitter'), f.jitter[0], f.jitter[1]);
  gl.uniform1f(at('u_bgAlpha'), f.bgAlpha);
  if (f.camera) {
    const camera = cameraUniforms(f.camera);
    if (!camera.every(finite)) throw new Error(`non-finite camera ${JSON.stringify(f.camera)}`);
    for (const u of camera) setUniform(gl, gp, u);
  }
}
