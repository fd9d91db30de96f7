/**
 * The resolve pass: turns an accumulation buffer into straight-alpha sRGB for the canvas or an
 * 8-bit readback. The buffer holds A = (Σ rgb·a, Σ a) over n samples (`sum` mode) or the running
 * mean of (rgb, a) (`mean` mode, where we pass n = 1); either way colour = A.rgb / A.a and
 * alpha = A.a / n. Into an sRGB framebuffer (SRGB8_ALPHA8: the readback target, the canvas where
 * srgb-canvas.ts got one) it writes linear light and the framebuffer encodes; only into a linear
 * one (RGBA8) does the shader encode, with shader-gen/srgb.ts linearToSrgb:
 * c ≤ 0.0031308 ? 12.92c : 1.055c^(1/2.4) − 0.055.
 */
import { toSrgbGlsl } from '../../shader-gen/glsl/colour.glsl.ts';
import { collectFunctions } from '../../shader-gen/glsl/snippet.ts';
import { VERTEX_SOURCE } from '../../shader-gen/glsl/template.ts';
import { bindProgram, buildProgram } from './gl-program.ts';

/** The fragment shader; `encode`: the shader applies the sRGB transfer function itself. */
const resolveFragment = (encode: boolean) => `#version 300 es
precision highp float;
uniform sampler2D u_accum;
uniform float u_count;
out vec4 outColor;
${encode ? collectFunctions([toSrgbGlsl]).join('\n') : ''}
void main() {
  vec4 acc = texelFetch(u_accum, ivec2(gl_FragCoord.xy), 0);
  vec3 straight = clamp(acc.a > 0.0 ? acc.rgb / acc.a : vec3(0.0), 0.0, 1.0);
  outColor = vec4(${encode ? 'toSrgb(straight)' : 'straight'}, clamp(acc.a / u_count, 0.0, 1.0));
}
`;

interface ResolveProgram {
  readonly program: WebGLProgram;
  readonly accum: WebGLUniformLocation | null;
  readonly count: WebGLUniformLocation | null;
}

function buildResolve(gl: WebGL2RenderingContext, encode: boolean): ResolveProgram {
  const built = buildProgram(gl, VERTEX_SOURCE, resolveFragment(encode));
  if (!built.ok) throw new Error(`resolve shader: ${built.error.map((d) => d.message).join('; ')}`);
  const program = built.value;
  return {
    program,
    accum: gl.getUniformLocation(program, 'u_accum'),
    count: gl.getUniformLocation(program, 'u_count'),
  };
}

export class ResolvePass {
  /** Writes linear light (the framebuffer encodes); the encoding one is built when first needed. */
  private readonly linear: ResolveProgram;
  private encoding: ResolveProgram | null = null;

  constructor(private readonly gl: WebGL2RenderingContext) {
    this.linear = buildResolve(gl, false);
  }

  /**
   * Draws `source` (at least width×height) into `framebuffer` (null: the canvas); see the header
   * for `count`. `srgbTarget`: the framebuffer is SRGB8_ALPHA8 and encodes on write.
   */
  draw(
    source: WebGLTexture,
    count: number,
    framebuffer: WebGLFramebuffer | null,
    width: number,
    height: number,
    srgbTarget: boolean,
  ): void {
    const gl = this.gl;
    if (!srgbTarget) this.encoding ??= buildResolve(gl, true);
    const pass = srgbTarget ? this.linear : (this.encoding as ResolveProgram);
    gl.bindFramebuffer(gl.FRAMEBUFFER, framebuffer);
    gl.viewport(0, 0, width, height);
    gl.disable(gl.BLEND);
    bindProgram(gl, pass.program);
    gl.activeTexture(gl.TEXTURE0);
    gl.bindTexture(gl.TEXTURE_2D, source);
    gl.uniform1i(pass.accum, 0);
    gl.uniform1f(pass.count, Math.max(1, count));
    gl.drawArrays(gl.TRIANGLES, 0, 3);
    gl.bindTexture(gl.TEXTURE_2D, null);
  }

  dispose(): void {
    if (this.gl.isContextLost()) return;
    this.gl.deleteProgram(this.linear.program);
    if (this.encoding) this.gl.deleteProgram(this.encoding.program);
  }
}
