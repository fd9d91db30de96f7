/**
 * The resolve pass: turns an accumulation buffer into straight-alpha sRGB for the canvas or an
 * 8-bit readback. The buffer holds A = (Σ rgb·a, Σ a) over n samples (`sum` mode) or the running
 * mean of (rgb, a) (`mean` mode, where we pass n = 1); either way colour = A.rgb / A.a and
 * alpha = A.a / n. sRGB encoding (shader-gen/srgb.ts linearToSrgb):
 * c ≤ 0.0031308 ? 12.92c : 1.055c^(1/2.4) − 0.055.
 */
import { toSrgbGlsl } from '../../shader-gen/glsl/colour.glsl.ts';
import { collectFunctions } from '../../shader-gen/glsl/snippet.ts';
import { VERTEX_SOURCE } from '../../shader-gen/glsl/template.ts';
import { bindProgram, buildProgram } from './gl-program.ts';

const RESOLVE_FRAGMENT = `#version 300 es
precision highp float;
uniform sampler2D u_accum;
uniform float u_count;
out vec4 outColor;
${collectFunctions([toSrgbGlsl]).join('\n')}
void main() {
  vec4 acc = texelFetch(u_accum, ivec2(gl_FragCoord.xy), 0);
  vec3 straight = acc.a > 0.0 ? acc.rgb / acc.a : vec3(0.0);
  outColor = vec4(toSrgb(clamp(straight, 0.0, 1.0)), clamp(acc.a / u_count, 0.0, 1.0));
}
`;

export class ResolvePass {
  private readonly program: WebGLProgram;
  private readonly accum: WebGLUniformLocation | null;
  private readonly count: WebGLUniformLocation | null;

  constructor(private readonly gl: WebGL2RenderingContext) {
    const built = buildProgram(gl, VERTEX_SOURCE, RESOLVE_FRAGMENT);
    if (!built.ok) throw new Error(`resolve shader: ${built.error.map((d) => d.message).join('; ')}`);
    this.program = built.value;
    this.accum = gl.getUniformLocation(this.program, 'u_accum');
    this.count = gl.getUniformLocation(this.program, 'u_count');
  }

  /** Draws `source` (at least width×height) into `framebuffer` (null: the canvas); see the header for `count`. */
  draw(
    source: WebGLTexture,
    count: number,
    framebuffer: WebGLFramebuffer | null,
    width: number,
    height: number,
  ): void {
    const gl = this.gl;
    gl.bindFramebuffer(gl.FRAMEBUFFER, framebuffer);
    gl.viewport(0, 0, width, height);
    gl.disable(gl.BLEND);
    bindProgram(gl, this.program);
    gl.activeTexture(gl.TEXTURE0);
    gl.bindTexture(gl.TEXTURE_2D, source);
    gl.uniform1i(this.accum, 0);
    gl.uniform1f(this.count, Math.max(1, count));
    gl.drawArrays(gl.TRIANGLES, 0, 3);
    gl.bindTexture(gl.TEXTURE_2D, null);
  }

  dispose(): void {
    if (!this.gl.isContextLost()) this.gl.deleteProgram(this.program);
  }
}
