/**
 * The video encoders of `kleinflow render --frames … --out x.webm|x.mp4`: Node has no WebCodecs,
 * so @mediabunny/server (Mediabunny's own Node extension) registers FFmpeg's libavcodec encoders,
 * from NodeAV's prebuilt native binary, behind the same mediabunny API the browser export uses
 * (src/io/animation-sink.ts). Imported on demand: a GIF, PNG frames and every other command never
 * load the native library, so they start as fast as before and work where it is missing.
 */
import { CliError, errorMessage } from './command.ts';

type ServerModule = Pick<typeof import('@mediabunny/server'), 'registerMediabunnyServer'>;

let registered: Promise<void> | undefined;

/**
 * Registers the encoders once per process. `hardwareContext: null` asks for software encoders
 * only: otherwise FFmpeg probes every GPU API on first use (CUDA, VAAPI, Vulkan, OpenCL, AMF) and
 * prints a line on stderr for each one this machine lacks, and a frame-sized software encode is
 * fast next to rendering the frame on the CPU. A native library that cannot load (no prebuilt
 * binary for this platform, a broken install) is one line saying what to do instead.
 */
export function loadVideoEncoders(
  load: () => Promise<ServerModule> = () => import('@mediabunny/server'),
): Promise<void> {
  registered ??= load()
    .then((server) => server.registerMediabunnyServer({ hardwareContext: null }))
    .catch((e: unknown) => {
      registered = undefined;
      const why = errorMessage(e).split('\n')[0];
      throw new CliError(
        `cannot load the video encoders (@mediabunny/server, FFmpeg through NodeAV's native binary for ${process.platform}-${process.arch}): ${why}. Write a GIF instead (--out loop.gif) or PNG frames (--out frames/), or reinstall with npm install`,
      );
    });
  return registered;
}
