/**
 * The print size (src/io/print-size.ts, docs/math-3d.md "Coloured mesh (paper Fig. 36)"): the
 * longest side of the scaled mesh is the print size whatever the mesh, the scaling is p → s·p
 * about the origin with the triangles untouched (so a closed mesh stays closed), typed sizes are
 * read or refused with a reason, and the size is written for people to a tenth of a millimetre.
 */
import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import type { Mesh } from '../../../nodes/geometry/space/marching-tetrahedra.ts';
import {
  formatPrintSize,
  MAX_PRINT_SIZE_MM,
  MIN_PRINT_SIZE_MM,
  meshExtent,
  millimetresPerUnit,
  parsePrintSize,
  scaleMesh,
} from '../../../src/io/print-size.ts';
import { unmatchedEdges } from '../../shader-gen/space/coloured-mesh.ts';

/** A tetrahedron with corners at `o`, o + (a, 0, 0), o + (0, b, 0), o + (0, 0, c). */
const tet = (o: readonly number[], a: number, b: number, c: number): Mesh => ({
  positions: Float64Array.from([
    o[0]!,
    o[1]!,
    o[2]!,
    o[0]! + a,
    o[1]!,
    o[2]!,
    o[0]!,
    o[1]! + b,
    o[2]!,
    o[0]!,
    o[1]!,
    o[2]! + c,
  ]),
  triangles: Uint32Array.from([0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3]),
});

describe('print size', () => {
  it('measures the bounding box and keeps one unit = 1 mm without a print size', () => {
    const m = tet([-1, 2, 0.5], 3, 1.5, 0.25);
    expect(meshExtent(m)).toEqual([3, 1.5, 0.25]);
    expect(millimetresPerUnit(meshExtent(m))).toBe(1);
    expect(millimetresPerUnit(meshExtent(m), 60)).toBe(20);
    expect(() => millimetresPerUnit([0, 0, 0], 60)).toThrow(/no size/);
  });

  it('scales about the origin: p → s·p, the triangles untouched, the longest side the print size', () => {
    fc.assert(
      fc.property(
        fc.array(fc.double({ min: -50, max: 50, noNaN: true }), { minLength: 3, maxLength: 3 }),
        fc.array(fc.double({ min: 0.01, max: 20, noNaN: true }), { minLength: 3, maxLength: 3 }),
        fc.double({ min: MIN_PRINT_SIZE_MM, max: MAX_PRINT_SIZE_MM, noNaN: true }),
        (o, [a, b, c], printSize) => {
          const m = tet(o, a!, b!, c!);
          const s = millimetresPerUnit(meshExtent(m), printSize);
          const scaled = scaleMesh(m, s);
          expect(scaled.triangles).toBe(m.triangles);
          expect(unmatchedEdges([...scaled.triangles])).toBe(0);
          for (const [i, v] of m.positions.entries()) expect(scaled.positions[i]).toBe(v * s);
          const longest = Math.max(...meshExtent(scaled));
          expect(Math.abs(longest - printSize)).toBeLessThanOrEqual(1e-9 * printSize);
        },
      ),
      { seed: 36, numRuns: 200 },
    );
  });

  it('reads "60", "60.5", "60 mm" and refuses other text and sizes out of range, saying why', () => {
    expect(parsePrintSize('60')).toEqual({ ok: true, value: 60 });
    expect(parsePrintSize(' 60.5 ')).toEqual({ ok: true, value: 60.5 });
    expect(parsePrintSize('60 mm')).toEqual({ ok: true, value: 60 });
    expect(parsePrintSize('1')).toEqual({ ok: true, value: 1 });
    expect(parsePrintSize('10000')).toEqual({ ok: true, value: 10_000 });
    for (const bad of ['', 'abc', '-5', '1e3', '6 0', '60cm', 'NaN', 'Infinity'])
      expect(parsePrintSize(bad)).toEqual({
        ok: false,
        error: expect.stringMatching(/millimetres, such as 60/),
      });
    for (const out of ['0', '0.5', '10000.5', '99999'])
      expect(parsePrintSize(out)).toEqual({
        ok: false,
        error: expect.stringMatching(/between 1 and 10000 mm/),
      });
  });

  it('writes the size to a tenth of a millimetre, two digits below 1 mm', () => {
    expect(formatPrintSize([1.466, 1.607, 1.576], 1)).toBe('1.5 × 1.6 × 1.6 mm');
    expect(formatPrintSize([1.466, 1.607, 1.576], 60 / 1.607)).toBe('54.7 × 60.0 × 58.8 mm');
    expect(formatPrintSize([0.0123, 0.5, 2], 1)).toBe('0.012 × 0.5 × 2.0 mm');
  });
});
