/**
 * The pictures a scene samples (picture colouring, picture seeds), decoded for the CPU raster.
 * Nodes keep pictures as data: URLs; the CLI decodes PNG ones with src/io/png.ts. Any other format
 * is an error that says what to do, never a silently wrong image.
 */
import { type Diagnostic, diag } from '../../nodes/core/diagnostics.ts';
import { tileImages, tileLiveSources } from '../../nodes/core/live-source.ts';
import type { Scene } from '../../nodes/core/scene.ts';
import { BUILTIN_PICTURE } from '../../nodes/core/values.ts';
import type { DecodedPicture } from '../../shader-gen/picture.ts';
import { decodePng } from '../io/png.ts';

/** Every picture src the scene uses (the built-in one excluded: the raster draws it). */
export function pictureSources(scene: Scene): string[] {
  // A live source's src is its fallback picture: the CLI has no camera or video, so draws that.
  const srcs = new Set(tileImages(scene.tile).map((image) => image.src));
  srcs.delete(BUILTIN_PICTURE.src);
  return [...srcs];
}

const PNG_DATA_URL = /^data:image\/png;base64,/i;

/** Decodes one data:image/png;base64 URL; throws a message naming the problem otherwise. */
export function decodePicture(src: string): DecodedPicture {
  const kind = src.slice(0, Math.max(0, src.indexOf(','))) || src.slice(0, 30);
  if (!PNG_DATA_URL.test(src))
    throw new Error(
      `the CLI renders pictures given as PNG data URLs only (got "${kind}"): convert the picture to PNG in the editor or an image tool`,
    );
  const bytes = Buffer.from(src.slice(src.indexOf(',') + 1), 'base64');
  try {
    return decodePng(new Uint8Array(bytes.buffer, bytes.byteOffset, bytes.byteLength));
  } catch (e) {
    throw new Error(`the picture (${kind}) could not be decoded: ${(e as Error).message}`);
  }
}

export function scenePictures(scene: Scene): Map<string, DecodedPicture> {
  return new Map(pictureSources(scene).map((src) => [src, decodePicture(src)]));
}

/** One note (KF324) per live source: the CLI has no camera or video, so it draws the fallback picture. */
export function liveFallbackNotes(scene: Scene): Diagnostic[] {
  return tileLiveSources(scene.tile).map((ref) =>
    diag(
      'liveFallback',
      { nodeId: ref.nodeId },
      ref.kind === 'webcam' ? 'the camera' : `the video “${ref.label}”`,
    ),
  );
}
