/**
 * Linked programs keyed by their fragment source (the one identity of a program, compile.ts): a
 * uniform program's text does not hold the values, so a value edit is a cache hit; a baked one's
 * does, so it is a hit only for the exact same values. Generating the text is cheap (`npm run
 * bench`, "Shader source per frame"), and the Map hashes it natively; keying on the whole text
 * rather than a digest means two programs can never collide. Least recently used programs beyond
 * the limit are deleted, so a long session does not leak.
 */
import type { Diagnostic } from '../../nodes/core/diagnostics.ts';
import { err, ok, type Result } from '../../nodes/core/result.ts';
import type { CompiledProgram, CompileOptions } from '../../shader-gen/compile.ts';
import { beginProgram, finishProgram, isProgramReady, type PendingProgram } from './gl-program.ts';
import { type GpuProgram, locateUniforms } from './uniforms.ts';

/** The cache key of a program: its fragment source (the vertex shader is the same for all). */
export const programKey = (compiled: CompiledProgram): string => compiled.source;

/** A compile started with `begin`, to be polled with `poll` (KHR_parallel_shader_compile). */
export interface PendingBuild {
  readonly key: string;
  readonly compiled: CompiledProgram;
  readonly pending: PendingProgram;
}

export class ProgramCache {
  private readonly programs = new Map<string, GpuProgram>();
  /** Programs the driver actually compiled (cache misses), uniform and baked counted apart. */
  compiles = 0;
  bakedCompiles = 0;

  constructor(
    private readonly gl: WebGL2RenderingContext,
    private readonly limit = 24,
  ) {}

  peek(key: string): GpuProgram | undefined {
    const gp = this.programs.get(key);
    if (gp) {
      // Re-insert: Map order is the LRU order.
      this.programs.delete(key);
      this.programs.set(key, gp);
    }
    return gp;
  }

  /** The program for `compiled`, compiling and linking it now on a miss. */
  obtain(compiled: CompiledProgram, options: CompileOptions): Result<GpuProgram, Diagnostic[]> {
    const key = programKey(compiled);
    const hit = this.peek(key);
    if (hit) return ok(hit);
    return this.complete(this.begin(compiled, options));
  }

  /** Starts compiling (returns at once with KHR_parallel_shader_compile; the link may still run). */
  begin(compiled: CompiledProgram, options: CompileOptions): PendingBuild {
    const key = programKey(compiled);
    if (options.baked) this.bakedCompiles++;
    else this.compiles++;
    return {
      key,
      compiled,
      pending: beginProgram(this.gl, compiled.vertexSource, compiled.source, compiled.lineMap),
    };
  }

  /** undefined while the driver is still busy; then the program (now cached) or the diagnostics. */
  poll(build: PendingBuild): Result<GpuProgram, Diagnostic[]> | undefined {
    if (!isProgramReady(this.gl, build.pending)) return undefined;
    return this.complete(build);
  }

  private complete(build: PendingBuild): Result<GpuProgram, Diagnostic[]> {
    const linked = finishProgram(this.gl, build.pending);
    if (!linked.ok) return err(linked.error);
    const gp = locateUniforms(this.gl, linked.value, build.compiled.uniforms);
    this.programs.set(build.key, gp);
    while (this.programs.size > this.limit) {
      const [oldest, old] = this.programs.entries().next().value as [string, GpuProgram];
      this.programs.delete(oldest);
      this.gl.deleteProgram(old.program);
    }
    return ok(gp);
  }

  /** Frees every program (skip when the context is lost: its objects are gone already). */
  dispose(): void {
    if (!this.gl.isContextLost()) for (const gp of this.programs.values()) this.gl.deleteProgram(gp.program);
    this.programs.clear();
  }
}
