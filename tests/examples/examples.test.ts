/**
 * Every example a user can open: loads without errors, explains itself (title + description a
 * teacher can read aloud), evaluates to a picture, and that picture is not blank.
 */
import { readFileSync } from 'node:fs';
import { describe, expect, it } from 'vitest';
import { evaluateGraph } from '../../nodes/graph/evaluate.ts';
import { parseDocumentText } from '../../nodes/graph/load.ts';
import { registry } from '../../nodes/types/index.ts';
import { rasterize } from '../../shader-gen/raster.ts';
import { exampleNames, examplePath } from '../../src/cli/examples.ts';
import { nodesOverlap, sizer } from '../../src/editor/layout.ts';

const names = exampleNames();

describe('examples', () => {
  it('there are at least 12', () => {
    expect(names.length).toBeGreaterThanOrEqual(12);
  });

  describe.each(names)('%s', (name) => {
    const loaded = parseDocumentText(readFileSync(examplePath(name), 'utf8'), registry);

    it('loads and evaluates with no error diagnostics', () => {
      expect(loaded.diagnostics).toEqual([]);
      if (!loaded.ok) return;
      const { diagnostics, scene } = evaluateGraph(loaded.doc, registry);
      expect(diagnostics.filter((d) => d.severity === 'error')).toEqual([]);
      expect(scene.renderNodeId).not.toBeNull();
      expect(scene.elements.length).toBeGreaterThanOrEqual(1);
    });

    it('has a title and a description', () => {
      if (!loaded.ok) throw new Error('does not load');
      expect(loaded.doc.meta.title?.trim().length).toBeGreaterThan(5);
      expect(loaded.doc.meta.description?.trim().length).toBeGreaterThan(80);
    });

    it('lays its nodes out on distinct positions, render node rightmost', () => {
      if (!loaded.ok) throw new Error('does not load');
      const nodes = loaded.doc.nodes;
      expect(new Set(nodes.map((n) => n.position.join(','))).size).toBe(nodes.length);
      const render = nodes.find((n) => n.type === 'render')!;
      expect(Math.max(...nodes.map((n) => n.position[0]))).toBe(render.position[0]);
      // With the editor's own node sizes nothing overlaps, so the example opens exactly as saved.
      expect(nodesOverlap(loaded.doc, sizer(loaded.doc, registry))).toBe(false);
    });

    it('renders a 64×64 picture that is not blank', () => {
      if (!loaded.ok) throw new Error('does not load');
      const { scene } = evaluateGraph(loaded.doc, registry);
      const { data } = rasterize(scene, { width: 64, height: 64, samples: 1 });
      const counts = new Map<number, number>();
      for (let i = 0; i < data.length; i += 4) {
        const key = (data[i] << 16) | (data[i + 1] << 8) | data[i + 2];
        counts.set(key, (counts.get(key) ?? 0) + 1);
      }
      expect(counts.size).toBeGreaterThanOrEqual(3); // two-tone examples: two tones + background
      expect(Math.max(...counts.values()) / (64 * 64)).toBeLessThanOrEqual(0.95);
    });
  });
});
