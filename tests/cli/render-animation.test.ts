/** `kleinflow render --time / --frames`: the real executable on the animated example. */
import { readdirSync, readFileSync, writeFileSync } from 'node:fs';
import { join } from 'node:path';
import { describe, expect, it } from 'vitest';
import { countGifFrames } from '../../src/io/gif.ts';
import { decodePng } from '../../src/io/png.ts';
import { cliTempDir, ROOT, runCli, runCliOk } from './run-cli.ts';

const ANIMATED = join(ROOT, 'examples/animated-breathing-loxodromic.kleinflow.json');
const SMALL = ['--size', '24x16', '--samples', '1'];
const dir = cliTempDir('kleinflow-anim-');
const bytes = (path: string) => new Uint8Array(readFileSync(path));
const pixels = (path: string) => decodePng(bytes(path)).data;

describe('kleinflow render --time', () => {
  it('renders the frame at time T; one loop (10 s) later it is the same picture', () => {
    const at = (t: string) => {
      const out = join(dir, `t${t}.png`);
      runCliOk(['render', ANIMATED, '--time', t, '-o', out, ...SMALL]);
      return pixels(out);
    };
    const first = at('0');
    expect(at('2.5')).not.toEqual(first);
    expect(at('10')).toEqual(first);
  });

  it('rejects a time that is not a number', () => {
    const r = runCli(['render', ANIMATED, '--time', 'soon', '-o', join(dir, 'x.png')]);
    expect(r.status).toBe(2);
    expect(r.stderr).toContain('--time expects seconds');
  });
});

describe('kleinflow render --frames', () => {
  it('writes a numbered PNG sequence, the same bytes run after run, splittable by --frame-range', () => {
    const run = (out: string, extra: string[] = []) => {
      const r = runCliOk([
        'render',
        ANIMATED,
        '--frames',
        '4',
        '--fps',
        '2',
        '--out',
        out,
        ...SMALL,
        ...extra,
      ]);
      return r;
    };
    const a = join(dir, 'seq-a');
    const r = run(a);
    expect(r.stdout).toContain('wrote 4 frames of 4 at 2 fps');
    const names = readdirSync(a).sort();
    expect(names).toEqual(['frame-00000.png', 'frame-00001.png', 'frame-00002.png', 'frame-00003.png']);
    // frame i is the still at t = i/fps
    const still = join(dir, 'still.png');
    expect(runCli(['render', ANIMATED, '--time', '1.5', '-o', still, ...SMALL]).status).toBe(0);
    expect(pixels(join(a, 'frame-00003.png'))).toEqual(pixels(still));
    expect(pixels(join(a, 'frame-00001.png'))).not.toEqual(pixels(join(a, 'frame-00000.png')));

    const b = join(dir, 'seq-b');
    run(b);
    for (const name of names) expect(bytes(join(b, name))).toEqual(bytes(join(a, name)));

    // Two halves rendered apart give the files of the whole run.
    const c = join(dir, 'seq-c');
    run(c, ['--frame-range', '0:2', '--threads', '1']);
    run(c, ['--frame-range', '2:']);
    expect(readdirSync(c).sort()).toEqual(names);
    for (const name of names) expect(bytes(join(c, name))).toEqual(bytes(join(a, name)));
  }, 120_000);

  it('writes a looping GIF with one image per frame; "loop" is one exact loop', () => {
    const gif = join(dir, 'loop.gif');
    runCliOk(['render', ANIMATED, '--frames', 'loop', '--fps', '1', '--out', gif, ...SMALL]);
    expect(countGifFrames(bytes(gif))).toBe(10); // the example loops every 10 s
    const again = join(dir, 'again.gif');
    runCli(['render', ANIMATED, '--frames', 'loop', '--fps', '1', '--out', again, ...SMALL]);
    expect(bytes(again)).toEqual(bytes(gif));
    // A loop that is not a whole number of frames is warned about: speed 3 → 10/3 s, at 2 fps 6.67.
    const fast = join(dir, 'fast.kleinflow.json');
    writeFileSync(fast, readFileSync(ANIMATED, 'utf8').replace('"speed": 1', '"speed": 3'));
    const w = runCli([
      'render',
      fast,
      '--frames',
      'loop',
      '--fps',
      '2',
      '--out',
      join(dir, 'fast.gif'),
      ...SMALL,
    ]);
    expect(w.status).toBe(0);
    expect(w.stderr).toMatch(
      /warning: one loop is 3\.333333 s, not a whole number of frames at 2 fps: 7 frames/,
    );
    expect(countGifFrames(bytes(join(dir, 'fast.gif')))).toBe(7);
  }, 120_000);

  it('says why a graph has no loop, and what a bad range is', () => {
    const still = join(ROOT, 'examples/hyperbolic-237.kleinflow.json');
    const r = runCli(['render', still, '--frames', 'loop', '--out', join(dir, 's.gif'), ...SMALL]);
    expect(r.status).toBe(1);
    expect(r.stderr).toContain('nothing in the graph changes with time');
    const bad = runCli([
      'render',
      ANIMATED,
      '--frames',
      '4',
      '--frame-range',
      '3:9',
      '--out',
      join(dir, 'b/'),
    ]);
    expect(bad.status).toBe(2);
    expect(bad.stderr).toContain('--frame-range must be between 0 and 4');
  });
});
