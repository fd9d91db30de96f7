/**
 * The program cache is keyed by the generated source (program-cache.ts): the real builder and cache
 * on a stand-in WebGL context that records every fragment shader the driver is asked to compile.
 * A drag (new values every frame) must compile nothing; a change of the code compiles once, and
 * going back to code seen before is a cache hit. The same in Chromium's WebGL:
 * viewport.browser.test.ts.
 */
import { readFileSync } from 'node:fs';
import { describe, expect, it } from 'vitest';
import type { Scene } from '../../../nodes/core/scene.ts';
import type { GraphDoc } from '../../../nodes/graph/document.ts';
import { evaluateGraph } from '../../../nodes/graph/evaluate.ts';
import { parseDocumentText } from '../../../nodes/graph/load.ts';
import { registry } from '../../../nodes/types/index.ts';
import { EXAMPLES_3D_DIR, examplePath } from '../../../src/cli/examples.ts';
import type { Drawable } from '../../../src/viewport/drawable.ts';
import { ProgramCache } from '../../../src/viewport/program-cache.ts';
import type { Renderer } from '../../../src/viewport/renderer.ts';
import { SceneProgramBuilder } from '../../../src/viewport/scene-program.ts';
import { loadExample, movePoint, sceneOf } from '../../support/examples.ts';

const FRAGMENT_SHADER = 0x8b30;

/** A WebGL2 context that compiles and links everything, recording the fragment sources compiled. */
function recordingGl(): { gl: WebGL2RenderingContext; fragments: string[] } {
  const fragments: string[] = [];
  const shaders = new Map<object, { type: number; source: string }>();
  const methods: Record<string, (...args: never[]) => unknown> = {
    createShader: (type: number) => {
      const s = {};
      shaders.set(s, { type, source: '' });
      return s;
    },
    shaderSource: (s: object, source: string) => {
      shaders.get(s)!.source = source;
    },
    compileShader: (s: object) => {
      const { type, source } = shaders.get(s)!;
      if (type === FRAGMENT_SHADER) fragments.push(source);
    },
    createProgram: () => ({}),
    getProgramParameter: () => true,
    getShaderParameter: () => true,
    getExtension: () => null,
    getUniformLocation: () => ({}),
    isContextLost: () => false,
  };
  const gl = new Proxy(
    {},
    {
      get: (_, name: string) =>
        name === 'FRAGMENT_SHADER'
          ? FRAGMENT_SHADER
          : /^[A-Z_]+$/.test(name)
            ? 1
            : (methods[name] ?? (() => {})),
    },
  ) as WebGL2RenderingContext;
  return { gl, fragments };
}

function setup() {
  const { gl, fragments } = recordingGl();
  const renderer = { programs: new ProgramCache(gl) } as unknown as Renderer;
  const builder = new SceneProgramBuilder(() => {});
  const apply = (scene: Drawable) => builder.apply(renderer, scene, 0);
  return { builder, renderer, fragments, apply };
}

describe('program cache keyed by the generated source', () => {
  const { doc, scene } = loadExample('apollonian-gasket');

  it('a drag (new values every frame) compiles nothing after the first frame', () => {
    const { builder, renderer, fragments, apply } = setup();
    expect(apply(scene)).toBe('code');
    expect(fragments).toHaveLength(1);
    const first = builder.current()!;
    for (let i = 1; i <= 30; i++) {
      expect(apply(sceneOf(movePoint(doc, 'tAB', 0.002 * i, -0.001 * i)))).toBe('values');
      // The same linked program, with the new values to upload.
      expect(builder.current()!.gp).toBe(first.gp);
      expect(builder.current()!.uniforms).not.toEqual(first.uniforms);
    }
    expect(fragments).toHaveLength(1);
    expect(builder.compiles(renderer)).toBe(1);
    // The same scene again: nothing changed at all.
    const last = sceneOf(movePoint(doc, 'tAB', 0.06, -0.03));
    expect(apply(last)).toBe('same');
  });

  it('a change of the code compiles once; going back to earlier code is a cache hit', () => {
    const { builder, renderer, fragments, apply } = setup();
    apply(scene);
    const fewer: Scene = { ...scene, elements: scene.elements.slice(1) };
    const edges: Scene = { ...scene, tile: { ...scene.tile, edgeWidth: scene.tile.edgeWidth > 0 ? 0 : 1 } };
    expect(apply(fewer)).toBe('code');
    expect(apply(edges)).toBe('code');
    expect(fragments).toHaveLength(3);
    expect(new Set(fragments).size).toBe(3);
    expect(apply(scene)).toBe('code');
    expect(apply(fewer)).toBe('code');
    expect(fragments).toHaveLength(3);
    expect(builder.compiles(renderer)).toBe(3);
  });
});

describe('3D scenes in the same program cache', () => {
  const loaded = parseDocumentText(
    readFileSync(examplePath('fig11-sphere-inversion-fractal', EXAMPLES_3D_DIR), 'utf8'),
    registry,
  );
  if (!loaded.ok) throw new Error('the Fig. 11 example does not load');
  const { doc } = loaded;
  const scene3dOf = (d: GraphDoc) => evaluateGraph(d, registry).scene3d!;
  const withSeedAt = (d: GraphDoc, center: [number, number, number]): GraphDoc => ({
    ...d,
    nodes: d.nodes.map((n) => (n.id === 'seed' ? { ...n, params: { ...n.params, center } } : n)),
  });

  it('a seed drag is a value change (no compile), a camera on the node is no change at all, and 3D never bakes', () => {
    const { builder, renderer, fragments, apply } = setup();
    expect(apply(scene3dOf(doc))).toBe('code');
    for (let i = 1; i <= 5; i++) expect(apply(scene3dOf(withSeedAt(doc, [0.01 * i, 0, 0])))).toBe('values');
    // The camera is a frame uniform (viewport.ts setCamera): it is not in the program or its values.
    const moved = scene3dOf(withSeedAt(doc, [0.05, 0, 0]));
    expect(apply({ ...moved, camera: { position: [9, 9, 9], target: [0, 0, 1], fovDeg: 30 } })).toBe('same');
    expect(fragments).toHaveLength(1);
    expect(builder.compiles(renderer)).toBe(1);
    expect(builder.bakeDueIn(1e9, 600)).toBeNull();
    expect(builder.exportProgram(renderer, moved).baked).toBe(false);
  });

  it('switching 2D → 3D → 2D compiles each once', () => {
    const { renderer, fragments, apply } = setup();
    const { scene } = loadExample('apollonian-gasket');
    expect(apply(scene)).toBe('code');
    expect(apply(scene3dOf(doc))).toBe('code');
    expect(apply(scene)).toBe('code');
    expect(fragments).toHaveLength(2);
    expect(renderer.programs.compiles).toBe(2);
  });
});
