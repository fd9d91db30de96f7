/**
 * When each frame of a recorded animation is taken: frame i shows time t_i = i / fps exactly
 * (computed from the integer i, never by adding 1/fps up, so frame 1000 has no drift and any
 * frame can be rendered alone — by another process — and match the sequence).
 */

/** t_i = i / fps, in seconds. */
export const frameTime = (index: number, fps: number): number => index / fps;

/**
 * Frames for one seamless loop of `seconds`: round(seconds · fps). The last frame is at
 * (n−1)/fps, one frame short of the loop end, so playing in a loop frame n−1 is followed by frame 0
 * = time L, the same picture. When seconds·fps is not whole the loop is off by under half a frame.
 */
export function loopFrameCount(seconds: number, fps: number): number {
  return Math.max(1, Math.round(seconds * fps));
}

/** Whether `seconds · fps` is a whole number of frames (to 1e-9), i.e. the loop closes exactly. */
export function loopIsFrameExact(seconds: number, fps: number): boolean {
  const n = seconds * fps;
  return Math.abs(n - Math.round(n)) <= 1e-9 * Math.max(1, n);
}
