/**
 * Every 3D example (examples/3d/): loads and evaluates without errors or warnings, explains
 * itself, lays its nodes out like the 2D examples, keeps its seeds in the fundamental domain, and
 * shows something: rays from its camera reach seed images for part of the view, not all of it.
 */
import { readFileSync } from 'node:fs';
import { describe, expect, it } from 'vitest';
import type { Scene3d, Vec3 } from '../../nodes/core/scene-3d.ts';
import { sampleSpace } from '../../nodes/core/seed-3d.ts';
import { add3, cross3, normalize3, scale3, sub3 } from '../../nodes/geometry/space/vec3.ts';
import { evaluateGraph } from '../../nodes/graph/evaluate.ts';
import { parseDocumentText } from '../../nodes/graph/load.ts';
import { registry } from '../../nodes/types/index.ts';
import { limitDots3d } from '../../shader-gen/space/limit-dots-3d.ts';
import { EXAMPLES_3D_DIR, exampleNames, examplePath } from '../../src/cli/examples.ts';
import { nodesOverlap, sizer } from '../../src/editor/layout.ts';

const names = exampleNames(EXAMPLES_3D_DIR);

/**
 * Whether the ray from the camera through normalised screen point (u, v) ∈ [−1, 1]² meets a seed
 * image (in a volume-rendered scene: a point of the depths it draws) within `far`: points along it at small steps, hit = the IIS carries one into a seed.
 * A brute-force test of the scene, independent of any distance estimate.
 */
function rayHits(scene: Scene3d, u: number, v: number, far: number, steps: number): boolean {
  const { position, target, fovDeg } = scene.camera;
  const forward = normalize3(sub3(target, position));
  const right = normalize3(cross3(forward, [0, 0, 1]));
  const up = cross3(right, forward);
  const t = Math.tan((fovDeg * Math.PI) / 360);
  const dir = normalize3(add3(forward, add3(scale3(right, u * t), scale3(up, v * t))));
  for (let i = 1; i <= steps; i++) {
    const p: Vec3 = add3(position, scale3(dir, (far * i) / steps));
    const s = sampleSpace(scene, p);
    // A volume-rendered example (Fig. 10) shows the mirrors' nesting depth, not the seed images.
    if (scene.volume ? s.depth >= scene.volume.depthFrom : s.distance !== null && s.distance < 0) return true;
  }
  return false;
}

describe('3D examples', () => {
  it('there are at least 8', () => {
    expect(names.length).toBeGreaterThanOrEqual(8);
  });

  describe.each(names)('%s', (name) => {
    const loaded = parseDocumentText(readFileSync(examplePath(name, EXAMPLES_3D_DIR), 'utf8'), registry);
    if (!loaded.ok) throw new Error(`${name} does not load`);
    const evaluation = evaluateGraph(loaded.doc, registry);

    it('evaluates to a 3D scene with no errors or warnings (but the one it is about)', () => {
      // The bridges/tunnels examples are outside the parameter space on purpose: their KF335 stays.
      const expected = /Fig\. 3[12] — (bridges|tunnels)/.test(loaded.doc.meta.title ?? '') ? ['KF335'] : [];
      const warnings = evaluation.diagnostics.filter((d) => d.severity !== 'info');
      expect(warnings.map((d) => d.code)).toEqual(expected);
      const scene = evaluation.scene3d!;
      expect(evaluation.scene.elements).toEqual([]);
      // A quaternion group's limit set (Fig. 6) is drawn as dots, with no seeds or elements.
      if (scene.limitSets?.length) return;
      // A sphairahedron's tile alone (Fig. 25) is a picture without elements; any other seed needs them.
      if (!scene.seeds.every((s) => s.kind === 'tile'))
        expect(scene.elements.length).toBeGreaterThanOrEqual(1);
      expect(scene.seeds.length).toBeGreaterThanOrEqual(1);
    });

    it('has a title and a description', () => {
      expect(loaded.doc.meta.title?.trim().length).toBeGreaterThan(5);
      expect(loaded.doc.meta.description?.trim().length).toBeGreaterThan(80);
    });

    it('lays its nodes out on distinct positions, render node rightmost, none overlapping', () => {
      const nodes = loaded.doc.nodes;
      expect(new Set(nodes.map((n) => n.position.join(','))).size).toBe(nodes.length);
      const render = nodes.find((n) => n.type === 'render-3d')!;
      expect(Math.max(...nodes.map((n) => n.position[0]))).toBe(render.position[0]);
      expect(nodesOverlap(loaded.doc, sizer(loaded.doc, registry))).toBe(false);
    });

    it('shows seed images (or limit-set dots) on 5 %–95 % of a 15×15 grid of camera rays', () => {
      const scene = evaluation.scene3d!;
      if (scene.limitSets?.length) {
        // Fig. 6: the dots of a small render fall in 5 %–95 % of the 15×15 cells of the view.
        const cells = new Set(
          limitDots3d(scene, 150, 150).dots.map((d) => `${Math.floor(d.x / 10)},${Math.floor(d.y / 10)}`),
        );
        expect(cells.size).toBeGreaterThanOrEqual(0.05 * 225);
        expect(cells.size).toBeLessThanOrEqual(0.95 * 225);
        return;
      }
      const far = 2 * Math.hypot(...sub3(scene.camera.target, scene.camera.position));
      let hits = 0;
      for (let i = 0; i < 15; i++)
        for (let j = 0; j < 15; j++) if (rayHits(scene, i / 7 - 1, j / 7 - 1, far, 300)) hits++;
      expect(hits).toBeGreaterThanOrEqual(0.05 * 225);
      expect(hits).toBeLessThanOrEqual(0.95 * 225);
    });
  });
});
