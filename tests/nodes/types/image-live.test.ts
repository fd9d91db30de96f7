import { describe, expect, it } from 'vitest';
import { parseLiveKey, pictureKey, tileLiveSources } from '../../../nodes/core/live-source.ts';
import type { TileSpec } from '../../../nodes/core/scene.ts';
import { BUILTIN_PICTURE, type ImageRef } from '../../../nodes/core/values.ts';
import { evaluateGraph } from '../../../nodes/graph/evaluate.ts';
import { registry } from '../../../nodes/types/index.ts';
import { compile } from '../../../shader-gen/compile.ts';
import { rasterize } from '../../../shader-gen/raster.ts';
import { makeScene, reflection } from '../../shader-gen/support/scenes.ts';
import { doc, edge, node } from '../support/doc.ts';

const PNG_1x1 = 'data:image/png;base64,iVBORw0KGgo=';

/** The image node `pic` (with `params`) wired into a picture tile: its image and the tile. */
function evaluate(params: Record<string, unknown>) {
  const ev = evaluateGraph(
    doc(
      [node('pic', 'image', params), node('t', 'tile', { mode: 'image' })],
      [edge('e1', 'pic.image', 't.image')],
    ),
    registry,
  );
  const pic = ev.nodes.get('pic')!;
  return { image: pic.outputs!.image as ImageRef, pic, tile: ev.nodes.get('t')!.outputs!.tile as TileSpec };
}

const imageScene = (image: ImageRef) =>
  makeScene([reflection('m', [0, 0], [0, 1])], {
    coloring: { mode: 'image', image, center: [0, 0], size: 1, rotation: 0 },
  });

describe('the image node’s source', () => {
  it('defaults to the picture: an old document gives the same image as before, no live source', () => {
    const { image, pic } = evaluate({});
    expect(image).toEqual(BUILTIN_PICTURE);
    expect(pic.readout).toBe('built-in checker');
  });

  it('webcam: the picture stays as the fallback and the image names the camera and the node', () => {
    const { image, pic, tile } = evaluate({ source: 'webcam', src: PNG_1x1, width: 4, height: 3 });
    expect(image).toMatchObject({ src: PNG_1x1, width: 4, height: 3 });
    expect(image.live).toEqual({ kind: 'webcam', nodeId: 'pic', label: '', src: '' });
    expect(pic.readout).toBe('camera; fallback: 4 × 3');
    expect(tileLiveSources(tile)).toEqual([image.live]);
  });

  it('video: keeps the file’s name and a small kept video; a kept video that is not one is refused (KF323)', () => {
    const kept = 'data:video/webm;base64,GkXfow==';
    const ok = evaluate({ source: 'video', video: 'loop.webm', videoSrc: kept });
    expect(ok.image.live).toEqual({ kind: 'video', nodeId: 'pic', label: 'loop.webm', src: kept });
    expect(ok.pic.diagnostics).toEqual([]);
    const bad = evaluate({ source: 'video', video: 'x.webm', videoSrc: 'data:text/plain,hello' });
    expect(bad.image.live?.src).toBe('');
    expect(bad.pic.diagnostics.map((d) => d.code)).toEqual(['KF323']);
  });
});

describe('live picture keys', () => {
  it('a plain picture’s key is its src; a live one names source, aspect and fallback, and parses back', () => {
    expect(pictureKey(BUILTIN_PICTURE)).toBe(BUILTIN_PICTURE.src);
    expect(parseLiveKey(BUILTIN_PICTURE.src)).toBeNull();
    const live = { kind: 'video', nodeId: 'a|b', label: 'v', src: '' } as const;
    const key = pictureKey({ src: PNG_1x1, width: 4, height: 3, live });
    expect(parseLiveKey(key)).toEqual({ source: 'video:a%7Cb', aspect: 4 / 3, fallback: PNG_1x1 });
  });

  it('switching a picture to a live source changes the sampled key but not the shader text', () => {
    const picture = compile(imageScene(BUILTIN_PICTURE));
    const camera = compile(
      imageScene({ ...BUILTIN_PICTURE, live: { kind: 'webcam', nodeId: 'pic', label: '', src: '' } }),
    );
    expect(camera.source).toBe(picture.source);
    expect(picture.pictures).toEqual([BUILTIN_PICTURE.src]);
    expect(parseLiveKey(camera.pictures[0])?.fallback).toBe(BUILTIN_PICTURE.src);
  });

  it('the CPU renderer draws a live image’s fallback picture', () => {
    const size = { width: 8, height: 8, samples: 1 };
    const live = { kind: 'webcam', nodeId: 'pic', label: '', src: '' } as const;
    const withCamera = rasterize(imageScene({ ...BUILTIN_PICTURE, live }), size);
    expect(withCamera).toEqual(rasterize(imageScene(BUILTIN_PICTURE), size));
  });
});
