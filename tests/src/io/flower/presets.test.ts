/**
 * The original Flower editor's five presets (read from ../shared, never copied into the project):
 * each imports, keeps its mirrors' exact coordinates and sides, evaluates cleanly and draws.
 */
import { existsSync, readdirSync, readFileSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import { describe, expect, it } from 'vitest';
import type { InversionElement, ReflectionElement } from '../../../../nodes/core/scene.ts';
import { pixelToWorld } from '../../../../nodes/core/view.ts';
import { evaluateGraph } from '../../../../nodes/graph/evaluate.ts';
import { registry } from '../../../../nodes/types/index.ts';
import { interpret } from '../../../../shader-gen/interpret.ts';
import { rasterize } from '../../../../shader-gen/raster.ts';
import { importFlower } from '../../../../src/io/flower/import.ts';
import { flowerMirrors, inFlowerTile, keptNormal } from './support/flower-reference.ts';

const PRESETS = fileURLToPath(new URL('../../../../../shared/reference/flower-presets/', import.meta.url));
const available = existsSync(PRESETS);

describe.skipIf(!available)('Flower presets (../shared/reference/flower-presets)', () => {
  const names = available
    ? readdirSync(PRESETS)
        .filter((f) => f.endsWith('.json'))
        .sort()
    : [];

  it('finds the five presets', () => {
    expect(names).toEqual(['angled.json', 'circles.json', 'rect.json', 'sinwave.json', 'triangle.json']);
  });

  for (const name of names) {
    describe(name, () => {
      const json = JSON.parse(readFileSync(PRESETS + name, 'utf8'));
      const result = importFlower(json);
      if (!result.ok) throw new Error(result.diagnostics.map((d) => d.message).join('\n'));
      const ev = evaluateGraph(result.doc, registry);
      const mirrors = flowerMirrors(json);

      it('imports and evaluates with no errors', () => {
        expect(ev.diagnostics.filter((d) => d.severity === 'error')).toEqual([]);
        expect(result.doc.meta.title).toBe(json.name);
      });

      it("its mirrors sit exactly on the preset's points, circles first", () => {
        const n = mirrors.circles.length;
        expect(ev.scene.elements.map((e) => e.kind)).toEqual([
          ...Array(n).fill('inversion'),
          ...Array(mirrors.lines.length).fill('reflection'),
        ]);
        mirrors.circles.forEach((c, i) => {
          const el = ev.scene.elements[i] as InversionElement;
          expect(el.c[0]).toBeCloseTo(c.c[0], 9);
          expect(el.c[1]).toBeCloseTo(c.c[1], 9);
          expect(el.r).toBeCloseTo(c.r, 9);
        });
        mirrors.lines.forEach((m, i) => {
          const el = ev.scene.elements[n + i] as ReflectionElement;
          expect(el.q).toEqual(m.p1);
          // Kleinflow's inside is (p − q)·n < 0, so n points into the kept side, as Flower's does.
          const kept = keptNormal(m);
          expect(el.n[0]).toBeCloseTo(kept[0], 12);
          expect(el.n[1]).toBeCloseTo(kept[1], 12);
        });
      });

      it("Flower's tile and Kleinflow's tile are the same region (mirror sides match)", () => {
        let inTile = 0;
        const size = 48;
        for (let py = 0; py < size; py++) {
          for (let px = 0; px < size; px++) {
            const p = pixelToWorld(ev.scene.view, size, size, px, py);
            const flower = inFlowerTile(mirrors, [p[0], p[1]]);
            const r = interpret(ev.scene, p);
            expect({ p, tile: r.escaped && r.depth === 0 }).toEqual({ p, tile: flower });
            if (flower) inTile++;
          }
        }
        expect(inTile).toBeGreaterThan(0);
        if (mirrors.lines.length + mirrors.circles.length > 0) expect(inTile).toBeLessThan(size * size);
      });

      it('renders a 64×64 image like Flower: the tile black, a pattern wherever the preset has mirrors', () => {
        const img = rasterize(ev.scene, { width: 64, height: 64, samples: 1 });
        const colours = new Set<number>();
        let lit = 0;
        let black = 0;
        for (let i = 0; i < img.data.length; i += 4) {
          colours.add((img.data[i] << 16) | (img.data[i + 1] << 8) | img.data[i + 2]);
          const sum = img.data[i] + img.data[i + 1] + img.data[i + 2];
          if (sum > 60) lit++;
          if (sum === 0) black++;
        }
        // One sample per pixel: each pixel is the black tile (Flower leaves n = 0 uncoloured) or a
        // bright hue (S = V = 1), nothing in between.
        expect(lit + black).toBe(64 * 64);
        if (mirrors.lines.length + mirrors.circles.length > 0) expect(lit).toBeGreaterThan(64);
        // sinwave.json has no mirror nodes at all (only lines): Flower draws no pattern either.
        const expected = mirrors.lines.length + mirrors.circles.length > 0 ? 3 : 1;
        expect(colours.size).toBeGreaterThanOrEqual(expected);
      });
    });
  }
});
