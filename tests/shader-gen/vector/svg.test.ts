import { describe, expect, it } from 'vitest';
import { vectorPicture } from '../../../shader-gen/vector/enumerate.ts';
import { exportSvg } from '../../../shader-gen/vector/index.ts';
import { writeSvg } from '../../../shader-gen/vector/svg.ts';
import { loadExample } from '../../support/examples.ts';
import { parseXml } from '../../support/xml.ts';

const SIZE = { width: 640, height: 480, minRadius: 1 };

const parseSvg = (text: string): Document => parseXml(text);

/** The drawn circles and lines: everything inside the outer group (not the background or clip). */
const drawn = (doc: Document): Element[] => [
  ...doc.documentElement.querySelectorAll(':scope > g circle, :scope > g line'),
];

describe('exportSvg', () => {
  it('writes a well-formed SVG whose element count is the enumeration kept in view', () => {
    const { scene } = loadExample('apollonian-gasket');
    const result = exportSvg(scene, SIZE);
    if (!result.ok) throw new Error(result.message);
    const doc = parseSvg(result.svg);
    expect(doc.documentElement.getAttribute('viewBox')).toBe('0 0 640 480');
    expect(drawn(doc)).toHaveLength(result.edgeCount + result.seedCount);
    const picture = vectorPicture(scene, SIZE);
    if (!picture.ok) throw new Error(picture.message);
    expect(result.edgeCount).toBeGreaterThan(1000);
    expect(result.edgeCount).toBeLessThanOrEqual(picture.edges.length);
  });

  it('writes every enumerated curve when the view holds the whole picture', () => {
    const { scene } = loadExample('schottky-pair');
    const wide = { ...scene, view: { ...scene.view, scale: scene.view.scale * 4 } };
    const picture = vectorPicture(wide, SIZE);
    if (!picture.ok) throw new Error(picture.message);
    const { svg, edgeCount } = writeSvg(wide, picture, SIZE.width, SIZE.height);
    expect(edgeCount).toBe(picture.edges.length);
    expect(drawn(parseSvg(svg))).toHaveLength(edgeCount);
  });

  it('writes seed disks filled with their colour', () => {
    const { scene } = loadExample('fig13-hyperbolic-mobius');
    const result = exportSvg(scene, SIZE);
    if (!result.ok) throw new Error(result.message);
    expect(result.seedCount).toBeGreaterThan(10);
    const filled = drawn(parseSvg(result.svg)).filter((e) => e.getAttribute('fill'));
    expect(filled).toHaveLength(result.seedCount);
  });

  it('clips to the clip disk of a Poincaré-disk render', () => {
    const { scene } = loadExample('fig08-hyperbolic-tessellation');
    expect(scene.clip).not.toBeNull();
    const result = exportSvg(scene, SIZE);
    if (!result.ok) throw new Error(result.message);
    const doc = parseSvg(result.svg);
    expect(doc.querySelector('clipPath circle')).not.toBeNull();
    expect(doc.documentElement.querySelector(':scope > g')?.getAttribute('clip-path')).toBe('url(#clip)');
  });

  it('names the node that has no vector form', () => {
    const { scene } = loadExample('glide-reflection-frieze');
    const result = exportSvg(scene, SIZE);
    expect(result.ok).toBe(false);
    if (result.ok) return;
    const node = scene.elements.find((e) => e.kind === 'glide-reflection');
    expect(result.nodeId).toBe(node?.nodeId);
    expect(result.message).toContain(`"${node?.nodeId}"`);
    expect(result.message).toContain('glide-reflection');
  });

  it('names a seed picture, which has no vector form', () => {
    const { scene } = loadExample('seed-picture-orbit');
    const seed = scene.tile.seeds?.find((s) => s.kind === 'image');
    expect(seed).toBeDefined();
    const result = exportSvg(scene, SIZE);
    expect(result.ok).toBe(false);
    if (!result.ok) expect(result.message).toContain(`"${seed?.nodeId}" is a seed picture`);
  });

  it('refuses more elements than the cap with a message that says what to change', () => {
    const { scene } = loadExample('apollonian-gasket');
    const result = exportSvg(scene, { ...SIZE, maxElements: 500 });
    expect(result.ok).toBe(false);
    if (!result.ok) expect(result.message).toMatch(/more than 500 .*raise the minimum radius/);
  });

  it('writes fewer circles for a larger minimum radius', () => {
    const { scene } = loadExample('apollonian-gasket');
    const fine = exportSvg(scene, SIZE);
    const coarse = exportSvg(scene, { ...SIZE, minRadius: 8 });
    if (!fine.ok || !coarse.ok) throw new Error('export failed');
    expect(coarse.edgeCount).toBeLessThan(fine.edgeCount / 4);
  });
});
