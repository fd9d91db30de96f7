// A tiny self-contained WebGL2 harness injected into a blank Chromium page by the parity tests:
// full-screen triangle, RGBA32F framebuffer (EXT_color_buffer_float), readPixels FLOAT. It counts
// compileShader calls so a test can prove that new uniform values need no new program.
// Plain browser JavaScript (no imports, no build step): page.addScriptTag injects this file as is.
(() => {
  const harness = {
    gl: null,
    width: 0,
    height: 0,
    compileCount: 0,
    programs: [],
    /** Picture textures by src (src/viewport/picture-textures.ts's format: SRGB8_ALPHA8, LINEAR, REPEAT). */
    pictures: {},

    /** Uploads a picture (RGBA8 bytes as base64, row 0 = top) once per src. */
    picture(src, width, height, base64) {
      const gl = harness.gl;
      if (harness.pictures[src]) return;
      const bin = atob(base64);
      const bytes = new Uint8Array(bin.length);
      for (let i = 0; i < bin.length; i++) bytes[i] = bin.charCodeAt(i);
      const t = gl.createTexture();
      gl.activeTexture(gl.TEXTURE1);
      gl.bindTexture(gl.TEXTURE_2D, t);
      gl.pixelStorei(gl.UNPACK_ALIGNMENT, 1);
      gl.texImage2D(gl.TEXTURE_2D, 0, gl.SRGB8_ALPHA8, width, height, 0, gl.RGBA, gl.UNSIGNED_BYTE, bytes);
      gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MIN_FILTER, gl.LINEAR);
      gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MAG_FILTER, gl.LINEAR);
      gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_WRAP_S, gl.REPEAT);
      gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_WRAP_T, gl.REPEAT);
      gl.activeTexture(gl.TEXTURE0);
      harness.pictures[src] = t;
    },

    /** Creates the context and an RGBA32F render target of width × height. */
    init(width, height) {
      const canvas = document.createElement('canvas');
      canvas.width = width;
      canvas.height = height;
      document.body.appendChild(canvas);
      const gl = canvas.getContext('webgl2', { antialias: false, preserveDrawingBuffer: false });
      if (!gl) throw new Error('no WebGL2 context');
      if (!gl.getExtension('EXT_color_buffer_float')) throw new Error('no EXT_color_buffer_float');
      const compileShader = gl.compileShader.bind(gl);
      gl.compileShader = (shader) => {
        harness.compileCount += 1;
        compileShader(shader);
      };
      const texture = gl.createTexture();
      gl.bindTexture(gl.TEXTURE_2D, texture);
      gl.texImage2D(gl.TEXTURE_2D, 0, gl.RGBA32F, width, height, 0, gl.RGBA, gl.FLOAT, null);
      gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MIN_FILTER, gl.NEAREST);
      gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MAG_FILTER, gl.NEAREST);
      const fbo = gl.createFramebuffer();
      gl.bindFramebuffer(gl.FRAMEBUFFER, fbo);
      gl.framebufferTexture2D(gl.FRAMEBUFFER, gl.COLOR_ATTACHMENT0, gl.TEXTURE_2D, texture, 0);
      const status = gl.checkFramebufferStatus(gl.FRAMEBUFFER);
      if (status !== gl.FRAMEBUFFER_COMPLETE)
        throw new Error(`framebuffer incomplete: 0x${status.toString(16)}`);
      gl.bindVertexArray(gl.createVertexArray());
      gl.viewport(0, 0, width, height);
      Object.assign(harness, { gl, width, height });
      return gl.getParameter(gl.RENDERER);
    },

    /** Compiles and links; returns the program's index, or throws with the compiler's log. */
    program(vertexSource, fragmentSource) {
      const gl = harness.gl;
      const shader = (type, source) => {
        const s = gl.createShader(type);
        gl.shaderSource(s, source);
        gl.compileShader(s);
        if (!gl.getShaderParameter(s, gl.COMPILE_STATUS))
          throw new Error(gl.getShaderInfoLog(s) || 'compile failed');
        return s;
      };
      const p = gl.createProgram();
      gl.attachShader(p, shader(gl.VERTEX_SHADER, vertexSource));
      gl.attachShader(p, shader(gl.FRAGMENT_SHADER, fragmentSource));
      gl.linkProgram(p);
      if (!gl.getProgramParameter(p, gl.LINK_STATUS))
        throw new Error(gl.getProgramInfoLog(p) || 'link failed');
      harness.programs.push(p);
      return harness.programs.length - 1;
    },

    /** Sets uniforms ({ name, type, value }[], arrays flattened) on the current program. */
    setUniforms(p, uniforms) {
      const gl = harness.gl;
      for (const u of uniforms) {
        const arrayName = u.type.endsWith('[]') ? `${u.name}[0]` : u.name;
        const loc = gl.getUniformLocation(p, arrayName);
        if (loc === null) continue; // declared but optimised away
        const v = new Float32Array(u.value);
        if (u.type === 'int') gl.uniform1i(loc, u.value[0]);
        else if (u.type === 'float' || u.type === 'float[]') gl.uniform1fv(loc, v);
        else if (u.type === 'vec2') gl.uniform2fv(loc, v);
        else if (u.type === 'vec3') gl.uniform3fv(loc, v);
        else gl.uniform4fv(loc, v);
      }
    },

    /**
     * Draws program `index` with scene uniforms and frame uniforms; returns the RGBA32F pixels
     * (row 0 at the bottom) as base64 of the float bytes, and the milliseconds the draw took.
     */
    render(index, uniforms, frame) {
      const gl = harness.gl;
      const p = harness.programs[index];
      // biome-ignore lint/correctness/useHookAtTopLevel: WebGL's useProgram, not a React hook
      gl.useProgram(p);
      harness.setUniforms(p, [
        ...uniforms,
        { name: 'u_resolution', type: 'vec2', value: frame.resolution ?? [harness.width, harness.height] },
        { name: 'u_pixelOffset', type: 'vec2', value: frame.pixelOffset ?? [0, 0] },
        { name: 'u_view', type: 'vec3', value: frame.view },
        { name: 'u_jitter', type: 'vec2', value: frame.jitter },
        { name: 'u_bgAlpha', type: 'float', value: [frame.bgAlpha ?? 1] },
        { name: 'iResolution', type: 'vec3', value: [harness.width, harness.height, 1] },
      ]);
      // Picture N on texture unit N + 1 (unit 0 keeps the render target's texture).
      (frame.pictures ?? []).forEach((src, i) => {
        gl.activeTexture(gl.TEXTURE1 + i);
        gl.bindTexture(gl.TEXTURE_2D, harness.pictures[src]);
        const loc = gl.getUniformLocation(p, `u_image${i}`) ?? gl.getUniformLocation(p, `iChannel${i}`);
        if (loc !== null) gl.uniform1i(loc, i + 1);
      });
      gl.activeTexture(gl.TEXTURE0);
      const t0 = performance.now();
      gl.drawArrays(gl.TRIANGLES, 0, 3);
      const pixels = new Float32Array(harness.width * harness.height * 4);
      gl.readPixels(0, 0, harness.width, harness.height, gl.RGBA, gl.FLOAT, pixels);
      const ms = performance.now() - t0;
      const bytes = new Uint8Array(pixels.buffer);
      let text = '';
      for (let i = 0; i < bytes.length; i += 0x8000)
        text += String.fromCharCode(...bytes.subarray(i, i + 0x8000));
      return { data: btoa(text), ms };
    },
  };
  window.kfHarness = harness;
})();
