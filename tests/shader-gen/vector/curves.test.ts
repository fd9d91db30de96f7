import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import { type Curve, type Mirror, mirrorImage } from '../../../shader-gen/vector/curves.ts';

/** Points on a curve: a circle's points at angles t, a line's points q + t·(−n.y, n.x). */
const pointOn = (k: Curve, t: number): [number, number] =>
  k.kind === 'circle'
    ? [k.c[0] + k.r * Math.cos(t), k.c[1] + k.r * Math.sin(t)]
    : [k.q[0] - k.n[1] * t, k.q[1] + k.n[0] * t];

/** The mirror map on points: σ(p) = c + r²(p−c)/|p−c|², ρ(p) = p − 2((p−q)·n)n. */
function mapPoint(m: Mirror, p: [number, number]): [number, number] {
  if (m.kind === 'line') {
    const h = 2 * ((p[0] - m.q[0]) * m.n[0] + (p[1] - m.q[1]) * m.n[1]);
    return [p[0] - h * m.n[0], p[1] - h * m.n[1]];
  }
  const dx = p[0] - m.c[0];
  const dy = p[1] - m.c[1];
  const k = (m.r * m.r) / (dx * dx + dy * dy);
  return [m.c[0] + dx * k, m.c[1] + dy * k];
}

const distanceTo = (k: Curve, p: [number, number]): number =>
  k.kind === 'circle'
    ? Math.abs(Math.hypot(p[0] - k.c[0], p[1] - k.c[1]) - k.r)
    : Math.abs((p[0] - k.q[0]) * k.n[0] + (p[1] - k.q[1]) * k.n[1]);

const coord = fc.double({ min: -3, max: 3, noNaN: true });
const radius = fc.double({ min: 0.1, max: 2, noNaN: true });
const unit = fc
  .double({ min: 0, max: 2 * Math.PI, noNaN: true })
  .map((a): [number, number] => [Math.cos(a), Math.sin(a)]);
const circle = fc
  .record({ c: fc.tuple(coord, coord), r: radius })
  .map((x): Curve => ({ kind: 'circle', ...x }));
const line = fc.record({ q: fc.tuple(coord, coord), n: unit }).map((x): Curve => ({ kind: 'line', ...x }));
const curve = fc.oneof(circle, line);

describe('mirrorImage', () => {
  it('maps every point of the curve onto the image curve (inversions and reflections)', () => {
    fc.assert(
      fc.property(curve, curve, fc.double({ min: -1, max: 1, noNaN: true }), (m, k, t) => {
        const p = pointOn(k, t * 3);
        const mirrorCentre = m.kind === 'circle' ? m.c : null;
        // Points within reach of the inversion centre map too far out to compare meaningfully.
        fc.pre(!mirrorCentre || Math.hypot(p[0] - mirrorCentre[0], p[1] - mirrorCentre[1]) > 0.05);
        const image = mirrorImage(m, k);
        const q = mapPoint(m, p);
        const size = Math.max(1, Math.hypot(q[0], q[1]), image.kind === 'circle' ? image.r : 1);
        expect(distanceTo(image, q)).toBeLessThan(1e-7 * size);
      }),
      { seed: 2311, numRuns: 400 },
    );
  });

  it('turns a circle through the inversion centre into a line, and that line back', () => {
    const m: Mirror = { kind: 'circle', c: [0, 0], r: 2 };
    const k: Curve = { kind: 'circle', c: [1, 0], r: 1 };
    const image = mirrorImage(m, k);
    expect(image).toEqual({ kind: 'line', q: [2, 0], n: [1, 0] });
    const back = mirrorImage(m, image);
    expect(back.kind).toBe('circle');
    if (back.kind === 'circle') {
      expect(back.c[0]).toBeCloseTo(1, 12);
      expect(back.r).toBeCloseTo(1, 12);
    }
  });
});
