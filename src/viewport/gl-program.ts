/**
 * The one compile/link helper for every WebGL2 program in Kleinflow (generated IIS shaders, the
 * resolve pass, benchmarks). Failures come back as diagnostics (KF403) with the node that emitted
 * the offending line: the generated source puts `#line 1 N` before each node's block, so the
 * compiler reports `ERROR: N:line: …` and `lineMap[N]` names the node.
 */
import { type Diagnostic, diag } from '../../nodes/core/diagnostics.ts';
import { err, ok, type Result } from '../../nodes/core/result.ts';

/** Numbers of the GLSL source strings (set by `#line L N`) → id of the node that emitted them. */
export type LineMap = Readonly<Record<number, string>>;

/** A program whose shaders were handed to the driver; it may still be compiling in parallel. */
export interface PendingProgram {
  readonly program: WebGLProgram;
  readonly vertex: WebGLShader;
  readonly fragment: WebGLShader;
  readonly lineMap: LineMap;
}

/** KHR_parallel_shader_compile's query enum (COMPLETION_STATUS_KHR). */
const COMPLETION_STATUS_KHR = 0x91b1;

/** `ERROR: 0:27: 'x' : undeclared identifier` → source string 0, line 27, the message. */
const LOG_LINE = /^(ERROR|WARNING):\s*(\d+):(\d+):\s*(.*)$/;

/**
 * Turns a driver info log into diagnostics, one per `ERROR:` line (warnings are dropped: drivers
 * disagree on them). Lines that do not match the pattern are reported as they are, without a node.
 */
export function parseInfoLog(log: string, lineMap: LineMap, stage: 'vertex' | 'fragment'): Diagnostic[] {
  const out: Diagnostic[] = [];
  for (const raw of log.split('\n')) {
    const text = raw.replace(/\0/g, '').trim();
    if (text === '') continue;
    const m = LOG_LINE.exec(text);
    if (!m) {
      if (!/^WARNING/i.test(text)) out.push(diag('shaderCompile', {}, `${stage} shader: ${text}`));
      continue;
    }
    if (m[1] === 'WARNING') continue;
    const source = Number(m[2]);
    const nodeId = stage === 'fragment' ? lineMap[source] : undefined;
    const where = nodeId === undefined ? `${stage} shader line ${m[3]}` : `node "${nodeId}", line ${m[3]}`;
    out.push(diag('shaderCompile', nodeId === undefined ? {} : { nodeId }, `${where}: ${m[4]}`));
  }
  return out;
}

function shader(gl: WebGL2RenderingContext, type: number, source: string): WebGLShader {
  const s = gl.createShader(type);
  if (!s) throw new Error('WebGL could not create a shader (context lost?)');
  gl.shaderSource(s, source);
  gl.compileShader(s);
  return s;
}

/** Hands both shaders to the driver and starts linking; with KHR_parallel_shader_compile this returns at once. */
export function beginProgram(
  gl: WebGL2RenderingContext,
  vertexSource: string,
  fragmentSource: string,
  lineMap: LineMap = {},
): PendingProgram {
  const program = gl.createProgram();
  if (!program) throw new Error('WebGL could not create a program (context lost?)');
  const vertex = shader(gl, gl.VERTEX_SHADER, vertexSource);
  const fragment = shader(gl, gl.FRAGMENT_SHADER, fragmentSource);
  gl.attachShader(program, vertex);
  gl.attachShader(program, fragment);
  gl.linkProgram(program);
  return { program, vertex, fragment, lineMap };
}

/** Whether asking for the link status would not stall (always true without the extension). */
export function isProgramReady(gl: WebGL2RenderingContext, pending: PendingProgram): boolean {
  if (!gl.getExtension('KHR_parallel_shader_compile')) return true;
  return gl.getProgramParameter(pending.program, COMPLETION_STATUS_KHR) === true;
}

/** Waits for the driver (if needed) and returns the linked program, or the diagnostics; frees the rest. */
export function finishProgram(
  gl: WebGL2RenderingContext,
  pending: PendingProgram,
): Result<WebGLProgram, Diagnostic[]> {
  const { program, vertex, fragment, lineMap } = pending;
  const linked = gl.getProgramParameter(program, gl.LINK_STATUS) === true;
  let problems: Diagnostic[] = [];
  if (!linked) {
    for (const [s, stage] of [
      [vertex, 'vertex'],
      [fragment, 'fragment'],
    ] as const) {
      if (gl.getShaderParameter(s, gl.COMPILE_STATUS) !== true) {
        problems.push(...parseInfoLog(gl.getShaderInfoLog(s) ?? '', lineMap, stage));
      }
    }
    if (problems.length === 0) {
      const log = (gl.getProgramInfoLog(program) ?? '').trim();
      const why = gl.isContextLost() ? 'the WebGL context was lost' : log || 'link failed';
      problems = [diag('shaderCompile', {}, `link: ${why}`)];
    }
  }
  gl.detachShader(program, vertex);
  gl.detachShader(program, fragment);
  gl.deleteShader(vertex);
  gl.deleteShader(fragment);
  if (!linked) {
    gl.deleteProgram(program);
    return err(problems);
  }
  return ok(program);
}

/** Compile + link now (blocking): the common case. */
export function buildProgram(
  gl: WebGL2RenderingContext,
  vertexSource: string,
  fragmentSource: string,
  lineMap: LineMap = {},
): Result<WebGLProgram, Diagnostic[]> {
  return finishProgram(gl, beginProgram(gl, vertexSource, fragmentSource, lineMap));
}

/** gl.useProgram behind a name the React-hooks lint rule does not mistake for a hook. */
export function bindProgram(gl: WebGL2RenderingContext, program: WebGLProgram | null): void {
  // biome-ignore lint/correctness/useHookAtTopLevel: WebGL's useProgram is not a React hook
  gl.useProgram(program);
}
