/**
 * Which program draws the current scene (2D or 3D, drawable.ts): its uniform program (the same source, so the same
 * program, for every value edit), or, after a quiet spell, the baked program of its exact values. Reports the
 * compiler's and the driver's diagnostics whenever they change, and keeps the compile counts
 * across context losses.
 */
import type { Diagnostic } from '../../nodes/core/diagnostics.ts';
import type { CompiledProgram, CompileOptions } from '../../shader-gen/compile.ts';
import type { UniformEntry } from '../../shader-gen/glsl/values.ts';
import { type Drawable, generateProgram as generate, is3d } from './drawable.ts';
import { type PendingBuild, programKey } from './program-cache.ts';
import type { Renderer } from './renderer.ts';
import type { GpuProgram } from './uniforms.ts';

export interface SceneProgram {
  readonly gp: GpuProgram;
  readonly uniforms: readonly UniformEntry[];
  readonly baked: boolean;
  /** The pictures it samples, by texture unit (CompiledProgram.pictures). */
  readonly pictures: readonly string[];
}

/** What a new scene changed: nothing that shows, only values (same source), or the code. */
export type SceneChange = 'same' | 'values' | 'code';

const UNIFORM: CompileOptions = { variant: 'color' };
const BAKED: CompileOptions = { variant: 'color', baked: true };

/**
 * Whether a scene gets the baked program (idle bake, export). Not a 3D one: its camera is a frame
 * uniform, so the picture converges on the uniform program before a bake would be due, and the
 * sphere tracer's baked program is far costlier to build — in SwiftShader about 20 s of a blocked
 * page to compile and as long again to link (the uniform program draws a sample in about 60 ms
 * at 200 × 350 px), frozen again after every edit.
 */
const bakes = (scene: Drawable): boolean => !is3d(scene);

function sameUniforms(a: readonly UniformEntry[], b: readonly UniformEntry[]): boolean {
  if (a.length !== b.length) return false;
  for (let i = 0; i < a.length; i++) {
    const x = a[i];
    const y = b[i];
    if (x.name !== y.name || x.type !== y.type || x.value.length !== y.value.length) return false;
    for (let j = 0; j < x.value.length; j++) if (!Object.is(x.value[j], y.value[j])) return false;
  }
  return true;
}

const samePictures = (a: readonly string[], b: readonly string[]) =>
  a.length === b.length && a.every((src, i) => src === b[i]);

export class SceneProgramBuilder {
  private compiled: CompiledProgram | null = null;
  private program: SceneProgram | null = null;
  /** Bumped by every change that shows; the bake belongs to one version. */
  private version = 0;
  private changedAt = 0;
  private bake: {
    version: number;
    compiled: CompiledProgram;
    build: PendingBuild | null;
    done: boolean;
  } | null = null;
  private reported: string | null = null;
  /** Whether the last applied scene is one that bakes (see `bakes`). */
  private bakeable = true;
  private compilesBefore = 0;
  private bakedBefore = 0;

  constructor(private readonly onDiagnostics: (d: Diagnostic[]) => void) {}

  /** Takes `scene`: compiles only when its generated source is new to the cache. */
  apply(renderer: Renderer, scene: Drawable, now: number): SceneChange {
    this.bakeable = bakes(scene);
    const compiled = generate(scene, UNIFORM);
    if (Array.isArray(compiled)) {
      this.fail(compiled);
      return 'code';
    }
    const prev = this.compiled;
    const sameSource = prev !== null && prev.source === compiled.source;
    if (
      sameSource &&
      this.program &&
      sameUniforms(prev.uniforms, compiled.uniforms) &&
      samePictures(prev.pictures, compiled.pictures)
    )
      return 'same';
    this.compiled = compiled;
    this.version++;
    this.changedAt = now;
    this.bake = null;
    const built = renderer.programs.obtain(compiled, UNIFORM);
    if (built.ok) {
      this.program = {
        gp: built.value,
        uniforms: compiled.uniforms,
        baked: false,
        pictures: compiled.pictures,
      };
      this.report(compiled.diagnostics);
    } else {
      this.program = null;
      this.report([...compiled.diagnostics, ...built.error]);
    }
    return sameSource ? 'values' : 'code';
  }

  /** The uniform program of the last applied scene; null when it did not compile. */
  current(): SceneProgram | null {
    return this.program;
  }

  /**
   * Idle bake, one step per frame: once the scene has been still for idleMs, generate and start
   * compiling the baked program; in a later frame (when the driver is done) return it.
   */
  pollBake(renderer: Renderer, scene: Drawable, now: number, idleMs: number): SceneProgram | null {
    if (this.bakeDueIn(now, idleMs) !== 0) return null;
    if (!this.bake || this.bake.version !== this.version) {
      const compiled = generate(scene, BAKED);
      if (Array.isArray(compiled)) {
        this.bake = { version: this.version, compiled: this.compiled!, build: null, done: true };
        return null;
      }
      const hit = renderer.programs.peek(programKey(compiled));
      this.bake = { version: this.version, compiled, build: null, done: hit !== undefined };
      if (hit) return { gp: hit, uniforms: compiled.uniforms, baked: true, pictures: compiled.pictures };
      this.bake.build = renderer.programs.begin(compiled, BAKED);
      return null;
    }
    const result = this.bake.build ? renderer.programs.poll(this.bake.build) : undefined;
    if (!result) return null;
    this.bake.done = true;
    if (!result.ok) {
      // The uniform program works, so the picture is right; only the speed-up is lost.
      console.warn('[kleinflow] baked shader failed; staying on the uniform one', result.error);
      return null;
    }
    const { uniforms, pictures } = this.bake.compiled;
    return { gp: result.value, uniforms, baked: true, pictures };
  }

  bakeInFlight(): boolean {
    return this.bake !== null && !this.bake.done && this.bake.version === this.version;
  }

  /** Milliseconds until the bake is due (0: now), or null when there is nothing to bake. */
  bakeDueIn(now: number, idleMs: number): number | null {
    if (!this.program || !this.bakeable || !Number.isFinite(idleMs)) return null;
    if (this.bake && this.bake.version === this.version && this.bake.done) return null;
    if (this.bake && this.bake.version === this.version) return 0;
    return Math.max(0, this.changedAt + idleMs - now);
  }

  /** For export: the baked program of `scene` (built now) where it bakes, else its uniform program. */
  exportProgram(renderer: Renderer, scene: Drawable): SceneProgram {
    const problems: Diagnostic[] = [];
    for (const options of bakes(scene) ? [BAKED, UNIFORM] : [UNIFORM]) {
      const compiled = generate(scene, options);
      if (Array.isArray(compiled)) {
        problems.push(...compiled);
        continue;
      }
      const built = renderer.programs.obtain(compiled, options);
      if (built.ok)
        return {
          gp: built.value,
          uniforms: compiled.uniforms,
          baked: options.baked === true,
          pictures: compiled.pictures,
        };
      problems.push(...built.error);
    }
    throw new Error(`the scene does not compile: ${problems.map((d) => d.message).join('; ')}`);
  }

  /** The context is gone: keep the counts, forget every program (the next apply compiles afresh). */
  forget(renderer: Renderer | null): void {
    this.compilesBefore += renderer?.programs.compiles ?? 0;
    this.bakedBefore += renderer?.programs.bakedCompiles ?? 0;
    this.compiled = null;
    this.program = null;
    this.bake = null;
  }

  compiles(renderer: Renderer | null): number {
    return this.compilesBefore + (renderer?.programs.compiles ?? 0);
  }

  bakedCompiles(renderer: Renderer | null): number {
    return this.bakedBefore + (renderer?.programs.bakedCompiles ?? 0);
  }

  private fail(problems: Diagnostic[]): void {
    this.compiled = null;
    this.program = null;
    this.bake = null;
    this.version++;
    this.report(problems);
  }

  private report(diagnostics: readonly Diagnostic[]): void {
    const key = JSON.stringify(diagnostics);
    if (key === this.reported) return;
    this.reported = key;
    this.onDiagnostics([...diagnostics]);
  }
}
