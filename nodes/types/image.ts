/**
 * A picture for the image kaleidoscope and image seeds. The document keeps the picture inline as
 * a data: URL (the editor reads the file and fills src, width and height); without one, or when it
 * is unusable, the built-in procedural picture (a checker with an arrow) stands in, so there is
 * always something that shows orientation.
 */
import { defineNode } from '../core/define-node.ts';
import { diag } from '../core/diagnostics.ts';
import { LIMITS } from '../core/limits.ts';
import { BUILTIN_PICTURE, type ImageRef } from '../core/values.ts';

const MB = (chars: number) => `${(chars / (1024 * 1024)).toFixed(1)} MB`;

/** The picture the params describe, or the built-in one with the reason it was not used. */
export function pictureOf(src: string, width: number, height: number) {
  if (src === '') return { image: BUILTIN_PICTURE, problem: null };
  if (src.length > LIMITS.maxImageDataUrlChars)
    return {
      image: BUILTIN_PICTURE,
      problem: diag(
        'pictureTooBig',
        { path: 'src' },
        `${MB(src.length)} of data`,
        MB(LIMITS.maxImageDataUrlChars),
      ),
    };
  if (!/^data:image\/[a-z0-9.+-]+(;[^,]*)?,/i.test(src))
    return {
      image: BUILTIN_PICTURE,
      problem: diag('badPicture', {}, 'the source is not a data:image/… URL'),
    };
  if (!(Number.isInteger(width) && Number.isInteger(height) && width > 0 && height > 0))
    return {
      image: BUILTIN_PICTURE,
      problem: diag('badPicture', {}, `its size ${width} × ${height} is not known`),
    };
  const side = LIMITS.maxPictureSide;
  if (width > side || height > side)
    return {
      image: BUILTIN_PICTURE,
      problem: diag('pictureTooBig', {}, `${width} × ${height} pixels`, `${side} × ${side}`),
    };
  return { image: { src, width, height } satisfies ImageRef, problem: null };
}

export const imageNode = defineNode({
  type: 'image',
  version: 1,
  label: 'Picture',
  category: 'Colour',
  color: '#7bc96f',
  doc: 'A picture (PNG, JPEG, … kept in the document) for the image kaleidoscope or an image seed; without one, a built-in checker with an arrow.',
  inputs: {},
  outputs: { image: { type: 'image', label: 'picture' } },
  params: {
    src: {
      kind: 'string',
      default: '',
      // Twice the picture limit, so a slightly too big picture loads and says why it is not shown.
      maxLength: 2 * LIMITS.maxImageDataUrlChars,
      label: 'picture',
      doc: `a data:image URL (at most ${MB(LIMITS.maxImageDataUrlChars)}); empty = the built-in checker with an arrow`,
    },
    width: {
      kind: 'number',
      default: 0,
      min: 0,
      max: LIMITS.maxPictureSide,
      integer: true,
      label: 'width px',
    },
    height: {
      kind: 'number',
      default: 0,
      min: 0,
      max: LIMITS.maxPictureSide,
      integer: true,
      label: 'height px',
    },
  },
  evaluate: ({ params }) => {
    const { image, problem } = pictureOf(params.src, params.width, params.height);
    const readout = image === BUILTIN_PICTURE ? 'built-in checker' : `${image.width} × ${image.height}`;
    return { outputs: { image }, diagnostics: problem ? [problem] : [], readout };
  },
});
