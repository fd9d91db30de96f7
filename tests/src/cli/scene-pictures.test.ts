import { describe, expect, it } from 'vitest';
import type { Coloring } from '../../../nodes/core/scene.ts';
import { BUILTIN_PICTURE } from '../../../nodes/core/values.ts';
import { rasterize, sampleColour, sampleContext } from '../../../shader-gen/raster.ts';
import { toLinear } from '../../../shader-gen/srgb.ts';
import {
  decodePicture,
  liveFallbackNotes,
  pictureSources,
  scenePictures,
} from '../../../src/cli/scene-pictures.ts';
import { encodePng } from '../../../src/io/png.ts';
import { makeScene, reflection } from '../../shader-gen/support/scenes.ts';

/** A 1×1 orange PNG as a data: URL. */
const ORANGE = (() => {
  const png = encodePng({ width: 1, height: 1, data: new Uint8ClampedArray([255, 128, 0, 255]) });
  return `data:image/png;base64,${Buffer.from(png).toString('base64')}`;
})();

const pictureScene = (src: string) => {
  const coloring: Coloring = {
    mode: 'image',
    image: { src, width: 1, height: 1 },
    center: [0, 0],
    size: 1,
    rotation: 0,
  };
  return makeScene([reflection('m', [0, 0], [0, 1])], { coloring });
};

describe('the CLI decodes the pictures a scene uses', () => {
  it('a PNG data URL becomes the pixels the raster samples', () => {
    const scene = pictureScene(ORANGE);
    expect(pictureSources(scene)).toEqual([ORANGE]);
    const pictures = scenePictures(scene);
    const colour = sampleColour(scene, sampleContext(scene, pictures), 0.2, -0.3, 0.01, {
      x: 0,
      y: 0,
      s: 1,
      depth: 0,
    });
    const want = toLinear([1, 128 / 255, 0]);
    for (let k = 0; k < 3; k++) expect(colour[k]).toBeCloseTo(want[k], 6); // texels are float32
    const image = rasterize(scene, { width: 4, height: 4, samples: 1, pictures });
    expect([...image.data.slice(0, 4)]).toEqual([255, 128, 0, 255]);
  });

  it('the built-in picture needs no decoding', () => {
    expect(pictureSources(pictureScene(BUILTIN_PICTURE.src))).toEqual([]);
  });

  it('another format is refused with a message saying what to do', () => {
    expect(() => decodePicture('data:image/jpeg;base64,/9j/4AAQ')).toThrow(/PNG data URLs only.*image\/jpeg/);
    expect(() => decodePicture('data:image/png;base64,AAAA')).toThrow(/could not be decoded/);
  });
});

describe('a live source on the CLI', () => {
  it('decodes its fallback picture, and notes (KF324) that the fallback is drawn', () => {
    const scene = pictureScene(ORANGE);
    const coloring = scene.tile.coloring as Extract<Coloring, { mode: 'image' }>;
    const live = { kind: 'webcam', nodeId: 'cam', label: '', src: '' } as const;
    const withCamera = {
      ...scene,
      tile: { ...scene.tile, coloring: { ...coloring, image: { ...coloring.image, live } } },
    };
    expect(pictureSources(withCamera)).toEqual([ORANGE]);
    expect(liveFallbackNotes(withCamera)).toMatchObject([{ code: 'KF324', nodeId: 'cam' }]);
    expect(liveFallbackNotes(scene)).toEqual([]);
  });
});
