/**
 * The resolve pass: turns an accumulation buffer into straight-alpha sRGB for the canvas or an
 * 8-bit readback. The buffer holds A = (Σ rgb·a, Σ a) over n samples (`sum` mode) or the running
 * mean of (rgb, a) (`mean` mode, where we pass n = 1); either way colour = A.rgb / A.a and
 * alpha = A.a / n. Into an sRGB framebuffer (SRGB8_ALPHA8: the readback target, the canvas where
 * srgb-canvas.ts got one) it writes linear light and the framebuffer encodes; only into a linear
 * one (RGBA8) does the shader encode, with shader-gen/srgb.ts linearToSrgb:
 * c ≤ 0.0031308 ? 12.92c : 1.055c^(1/2.4) − 0.055.
 * A picture drawn smaller than its destination (the 3D pane's reduced frames, render-scale.ts)
 * covers the source's first u_source pixels and is stretched bilinearly over the destination;
 * at full size each pixel reads its own texel, exactly as before.
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
uniform vec2 u_source;      // the drawn region of u_accum, pixels
uniform vec2 u_destination; // the size drawn into, pixels
out vec4 outColor;
${encode ? collectFunctions([toSrgbGlsl]).join('\n') : ''}
vec4 resolved(ivec2 p) {
  vec4 acc = texelFetch(u_accum, clamp(p, ivec2(0), ivec2(u_source) - 1), 0);
  vec3 straight = clamp(acc.a > 0.0 ? acc.rgb / acc.a : vec3(0.0), 0.0, 1.0);
  return vec4(straight, clamp(acc.a / u_count, 0.0, 1.0));
}
void main() {
  vec4 c;
  if (u_source == u_destination) c = resolved(ivec2(gl_FragCoord.xy));
  else {
    // Bilinear between the four nearest drawn pixel centres (in linear light).
    vec2 at = gl_FragCoord.xy * u_source / u_destination - 0.5;
    ivec2 i = ivec2(floor(at));
    vec2 f = at - floor(at);
    c = mix(mix(resolved(i), resolved(i + ivec2(1, 0)), f.x),
            mix(resolved(i + ivec2(0, 1)), resolved(i + ivec2(1, 1)), f.x), f.y);
  }
  outColor = vec4(${encode ? 'toSrgb(c.rgb)' : 'c.rgb'}, c.a);
}
`;

interface ResolveProgram {
  readonly program: WebGLProgram;
  readonly accum: WebGLUniformLocation | null;
  readonly count: WebGLUniformLocation | null;
  readonly source: WebGLUniformLocation | null;
  readonly destination: WebGLUniformLocation | null;
}

/** A width×height region (of a source or destination), pixels. */
export interface Extent {
  readonly width: number;
  readonly height: number;
}

function buildResolve(gl: WebGL2RenderingContext, encode: boolean): ResolveProgram {
  const built = buildProgram(gl, VERTEX_SOURCE, resolveFragment(encode));
  if (!built.ok) throw new Error(`resolve shader: ${built.error.map((d) => d.message).join('; ')}`);
  const program = built.value;
  return {
    program,
    accum: gl.getUniformLocation(program, 'u_accum'),
    count: gl.getUniformLocation(program, 'u_count'),
    source: gl.getUniformLocation(program, 'u_source'),
    destination: gl.getUniformLocation(program, 'u_destination'),
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
   * for `count`. `srgbTarget`: the framebuffer is SRGB8_ALPHA8 and encodes on write. `drawn`: the
   * part of `source` holding the picture when it was drawn smaller (default: width×height).
   */
  draw(
    source: WebGLTexture,
    count: number,
    framebuffer: WebGLFramebuffer | null,
    width: number,
    height: number,
    srgbTarget: boolean,
    drawn: Extent = { width, height },
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
    gl.uniform2f(pass.source, drawn.width, drawn.height);
    gl.uniform2f(pass.destination, width, height);
    gl.drawArrays(gl.TRIANGLES, 0, 3);
    gl.bindTexture(gl.TEXTURE_2D, null);
  }

  dispose(): void {
    if (this.gl.isContextLost()) return;
    this.gl.deleteProgram(this.linear.program);
    if (this.encoding) this.gl.deleteProgram(this.encoding.program);
  }
}
