/** The CLI's video encoders load on demand; a native library that cannot load is one line saying what to do. */
import { describe, expect, it } from 'vitest';
import { CliError } from '../../src/cli/command.ts';
import { loadVideoEncoders } from '../../src/cli/video-encoders.ts';

describe('loadVideoEncoders', () => {
  it('turns a missing native binary into one line that suggests a GIF, and tries again next time', async () => {
    const missing = () =>
      Promise.reject(new Error('Cannot find module node-av-linux-x64/node-av.node\nRequire stack: …'));
    const failure = await loadVideoEncoders(missing).catch((e: unknown) => e);
    expect(failure).toBeInstanceOf(CliError);
    const message = (failure as CliError).message;
    expect(message).not.toContain('\n');
    expect(message).toContain('cannot load the video encoders');
    expect(message).toContain('Cannot find module node-av-linux-x64/node-av.node');
    expect(message).toContain('--out loop.gif');

    let options: unknown;
    await loadVideoEncoders(async () => ({
      registerMediabunnyServer: (o?: unknown) => {
        options = o;
      },
    }));
    // Software encoders only: no hardware probing (and none of FFmpeg's lines about it on stderr).
    expect(options).toEqual({ hardwareContext: null });
  });
});
