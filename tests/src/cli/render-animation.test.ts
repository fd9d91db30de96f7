import { describe, expect, it } from 'vitest';
import { CliError } from '../../../src/cli/command.ts';
import { frameFileName, parseFrameRange } from '../../../src/cli/render-animation.ts';

describe('--frame-range', () => {
  it('A:B is frames A to B−1; either end may be left out', () => {
    expect(parseFrameRange('0:48', 100)).toEqual({ start: 0, end: 48 });
    expect(parseFrameRange('48:', 100)).toEqual({ start: 48, end: 100 });
    expect(parseFrameRange(':10', 100)).toEqual({ start: 0, end: 10 });
  });

  it('says what is wrong with a bad range', () => {
    const message = (text: string) => {
      try {
        parseFrameRange(text, 100);
      } catch (e) {
        expect(e).toBeInstanceOf(CliError);
        return (e as Error).message;
      }
      return 'no error';
    };
    expect(message('5')).toMatch(/expects A:B/);
    expect(message('10:10')).toMatch(/holds no frame/);
    expect(message('0:101')).toMatch(/between 0 and 100/);
    expect(message('-1:4')).toMatch(/expects A:B/);
  });
});

describe('frame file names', () => {
  it('are numbered globally and padded to the whole sequence, so they sort', () => {
    expect(frameFileName(7, 10)).toBe('frame-00007.png');
    expect(frameFileName(123456, 200000)).toBe('frame-123456.png');
    expect(frameFileName(5, 200000)).toBe('frame-000005.png');
  });
});
