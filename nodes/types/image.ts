/**
 * A picture for the image kaleidoscope and image seeds. The document keeps the picture inline as
 * a data: URL (the editor reads the file and fills src, width and height); without one, or when it
 * is unusable, the built-in procedural picture (a checker with an arrow) stands in, so there is
 * always something that shows orientation. `source` can ask for a live source instead — the
 * camera or a looping video file — which the browser draws in the picture's place (cropped to its
 * aspect); the picture is then the fallback drawn wherever the source does not run (CLI, denied
 * camera). The document keeps only the choice, the video's name and, when small, the video.
 */
import { defineNode } from '../core/define-node.ts';
import { diag } from '../core/diagnostics.ts';
import { LIMITS } from '../core/limits.ts';
import { BUILTIN_PICTURE, type ImageRef, type LiveRef } from '../core/values.ts';

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

const VIDEO_DATA_URL = /^data:video\/[a-z0-9.+-]+(;[^,]*)?,/i;

/** The live source the params ask for (undefined for a plain picture), and why a kept video is not used. */
export function liveOf(nodeId: string, source: string, video: string, videoSrc: string) {
  if (source !== 'webcam' && source !== 'video') return { live: undefined, problem: null };
  if (source === 'webcam')
    return { live: { kind: 'webcam', nodeId, label: '', src: '' } satisfies LiveRef, problem: null };
  const tooBig = videoSrc.length > LIMITS.maxVideoDataUrlChars;
  const bad = videoSrc !== '' && !VIDEO_DATA_URL.test(videoSrc);
  const problem = tooBig
    ? diag(
        'videoUnplayable',
        { path: 'videoSrc' },
        `the kept video is ${MB(videoSrc.length)}, over ${MB(LIMITS.maxVideoDataUrlChars)}`,
      )
    : bad
      ? diag('videoUnplayable', { path: 'videoSrc' }, 'the kept video is not a data:video/… URL')
      : null;
  const live: LiveRef = { kind: 'video', nodeId, label: video, src: problem ? '' : videoSrc };
  return { live, problem };
}

export const imageNode = defineNode({
  type: 'image',
  version: 1,
  label: 'Picture',
  category: 'Colour',
  color: '#7bc96f',
  doc: 'A picture (PNG, JPEG, … kept in the document) for the image kaleidoscope or an image seed; without one, a built-in checker with an arrow. Source webcam or video draws the camera or a looping video live instead (the picture is the fallback).',
  inputs: {},
  outputs: { image: { type: 'image', label: 'picture' } },
  params: {
    source: {
      kind: 'enum',
      default: 'picture',
      options: ['picture', 'webcam', 'video'],
      label: 'source',
      doc: 'picture: the picture below; webcam / video: drawn live in the browser (the picture is the fallback)',
    },
    video: {
      kind: 'string',
      default: '',
      maxLength: 500,
      label: 'video file',
      when: { param: 'source', is: ['video'] },
      doc: 'the chosen video file’s name (a label: choose the file with “Choose video…”)',
    },
    videoSrc: {
      kind: 'string',
      default: '',
      maxLength: 2 * LIMITS.maxVideoDataUrlChars,
      label: 'kept video',
      // Only a video source has one; even then it is a long data URL, so it sits under More.
      when: { param: 'source', is: ['video'] },
      more: true,
      doc: `a small video kept inline (data:video URL, at most ${MB(LIMITS.maxVideoDataUrlChars)}); empty = choose the file after opening`,
    },
    src: {
      kind: 'string',
      default: '',
      // Twice the picture limit, so a slightly too big picture loads and says why it is not shown.
      maxLength: 2 * LIMITS.maxImageDataUrlChars,
      label: 'picture',
      doc: `a data:image URL (at most ${MB(LIMITS.maxImageDataUrlChars)}) — “Choose picture…” in the inspector fills it, shrinking a bigger picture to fit; empty = the built-in checker with an arrow`,
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
  evaluate: ({ params, nodeId }) => {
    const { image, problem } = pictureOf(params.src, params.width, params.height);
    const picture = image === BUILTIN_PICTURE ? 'built-in checker' : `${image.width} × ${image.height}`;
    const { live, problem: videoProblem } = liveOf(nodeId, params.source, params.video, params.videoSrc);
    const diagnostics = [problem, videoProblem].filter((d) => d !== null);
    if (!live) return { outputs: { image }, diagnostics, readout: picture };
    const name = live.kind === 'webcam' ? 'camera' : `video ${live.label || '(none chosen)'}`;
    return { outputs: { image: { ...image, live } }, diagnostics, readout: `${name}; fallback: ${picture}` };
  },
});
