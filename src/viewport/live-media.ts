/**
 * The page's live media: the camera (one stream, asked for only by `startCamera`, which the UI
 * calls from a click) and one looping, muted <video> per image node with source "video". Nothing
 * here is saved: the document keeps only which source a node wants (nodes/types/image.ts).
 * The viewport reads frames from `frameOf` each animation frame; the app reads `state` for the
 * node messages and the "Start camera" button, and `subscribe`s to hear when either changes.
 */

export type LiveStatus =
  | { readonly status: 'off' }
  | { readonly status: 'starting' }
  | { readonly status: 'live' }
  | { readonly status: 'failed'; readonly reason: string };

interface Source {
  state: LiveStatus;
  video: HTMLVideoElement | null;
  /** Frames the video has presented (requestVideoFrameCallback), to upload each only once. */
  frames: number;
  /** The video file's name (video sources), or '' for the camera. */
  name: string;
  /** A 'seeked' listener will follow the clock again (set while a seek runs). */
  followAfterSeek?: boolean;
  /** What the camera stream or object URL holds, released on stop. */
  release(): void;
}

const OFF: LiveStatus = { status: 'off' };

/** A frame to draw: the element and the count of frames it has presented (NaN: unknown, upload always). */
export interface LiveFrame {
  readonly video: HTMLVideoElement;
  readonly serial: number;
}

export class LiveMedia {
  private readonly sources = new Map<string, Source>();
  private readonly listeners = new Set<() => void>();
  /** The timeline's time (s) videos follow, or null: they play in real time. */
  private clock: number | null = null;

  /** The state of source `id` (`webcam` or `video:<node id>`, nodes/core/live-source.ts). */
  state(id: string): LiveStatus {
    return this.sources.get(id)?.state ?? OFF;
  }

  /** The sources started (any state). */
  ids(): string[] {
    return [...this.sources.keys()];
  }

  /** The video file's name the source `id` plays ('' when none). */
  videoName(id: string): string {
    return this.sources.get(id)?.name ?? '';
  }

  /** The source's current frame, or null while it is not live (the fallback is drawn then). */
  frameOf(id: string): LiveFrame | null {
    const s = this.sources.get(id);
    if (s?.state.status !== 'live' || !s.video) return null;
    if (s.video.readyState < HTMLMediaElement.HAVE_CURRENT_DATA || s.video.videoWidth === 0) return null;
    return { video: s.video, serial: 'requestVideoFrameCallback' in s.video ? s.frames : Number.NaN };
  }

  subscribe(listener: () => void): () => void {
    this.listeners.add(listener);
    return () => this.listeners.delete(listener);
  }

  /** Asks for the camera (call it from a user gesture: the browser may prompt). */
  async startCamera(): Promise<void> {
    const now = this.state('webcam').status;
    if (now === 'live' || now === 'starting') return;
    const source = this.put('webcam', '', { status: 'starting' }, null, () => {});
    try {
      if (!navigator.mediaDevices?.getUserMedia) throw new Error('this browser offers no camera access');
      const stream = await navigator.mediaDevices.getUserMedia({ video: true, audio: false });
      if (this.sources.get('webcam') !== source) {
        for (const t of stream.getTracks()) t.stop(); // stopped while the browser asked
        return;
      }
      const video = newVideo();
      video.srcObject = stream;
      source.release = () => {
        for (const t of stream.getTracks()) t.stop();
      };
      await this.play(source, video);
    } catch (e) {
      if (this.sources.get('webcam') === source) this.fail(source, cameraReason(e));
    }
  }

  /** Plays `src` (an object URL of a chosen file, or a kept data: URL) for video source `id`, looping. */
  async startVideo(id: string, src: string, name: string, revoke = false): Promise<void> {
    const source = this.put(id, name, { status: 'starting' }, null, () => {
      if (revoke) URL.revokeObjectURL(src);
    });
    const video = newVideo();
    video.src = src;
    try {
      await this.play(source, video);
    } catch (e) {
      if (this.sources.get(id) === source) this.fail(source, (e as Error).message || String(e));
    }
  }

  /** Stops and forgets source `id` (the camera light goes off). */
  stop(id: string): void {
    const s = this.sources.get(id);
    if (!s) return;
    this.sources.delete(id);
    s.release();
    s.video?.pause();
    this.changed();
  }

  /**
   * Videos follow the animation timeline: at time t they show t modulo their duration and stay
   * still while it is paused; null lets them play in real time, looping.
   */
  setClock(time: number | null): void {
    this.clock = time;
    for (const [id, s] of this.sources) if (id !== 'webcam') this.follow(s);
  }

  /**
   * For an export: every video is paused at timeline time t (t modulo its length) and this resolves
   * once each shows that frame, so frame i of an animation draws the video at i / fps. A video that
   * does not finish seeking within SEEK_WAIT_MS is drawn as it stands. `followClock` hands the
   * videos back to the timeline afterwards.
   */
  async seekVideos(time: number): Promise<void> {
    const seeks: Promise<void>[] = [];
    for (const [id, s] of this.sources) {
      const v = s.video;
      if (id === 'webcam' || !v || s.state.status !== 'live') continue;
      if (!v.paused) v.pause();
      const t = timelinePosition(time, v.duration);
      if (t === null) continue;
      // A new serial: the seeked frame is uploaded even if no video frame callback reports it.
      seeks.push(
        seekTo(v, t).then(() => {
          s.frames++;
        }),
      );
    }
    await Promise.all(seeks);
  }

  /** The videos follow the timeline's clock again (or play in real time), as before an export. */
  followClock(): void {
    this.setClock(this.clock);
  }

  private follow(s: Source): void {
    const v = s.video;
    if (!v || s.state.status !== 'live') return;
    if (this.clock === null) {
      if (v.paused) void v.play().catch(() => {});
      return;
    }
    if (!v.paused) v.pause();
    // While a seek runs, the next is set when it ends (a time set meanwhile would be lost: the
    // timeline may not tick again).
    if (v.seeking) {
      if (!s.followAfterSeek) {
        s.followAfterSeek = true;
        v.addEventListener(
          'seeked',
          () => {
            s.followAfterSeek = false;
            this.follow(s);
          },
          { once: true },
        );
      }
      return;
    }
    const t = timelinePosition(this.clock, v.duration);
    // A seek per timeline tick, but not for differences below a frame (seeking is not free).
    if (t !== null && Math.abs(v.currentTime - t) > 1 / 120) v.currentTime = t;
  }

  private put(
    id: string,
    name: string,
    state: LiveStatus,
    video: HTMLVideoElement | null,
    release: () => void,
  ) {
    const old = this.sources.get(id);
    if (old) {
      old.release();
      old.video?.pause();
    }
    const source: Source = { state, video, frames: 0, name, release };
    this.sources.set(id, source);
    this.changed();
    return source;
  }

  private async play(source: Source, video: HTMLVideoElement): Promise<void> {
    source.video = video;
    const count = () => {
      source.frames++;
      video.requestVideoFrameCallback(count);
    };
    if ('requestVideoFrameCallback' in video) video.requestVideoFrameCallback(count);
    await video.play();
    await knowDuration(video);
    source.state = { status: 'live' };
    this.follow(source);
    this.changed();
  }

  private fail(source: Source, reason: string): void {
    source.release();
    source.video?.pause();
    source.video = null;
    source.state = { status: 'failed', reason };
    console.warn(`[kleinflow] live source failed: ${reason}`);
    this.changed();
  }

  private changed(): void {
    for (const l of this.listeners) l();
  }
}

/**
 * Where a video of `duration` seconds stands at timeline time t: t mod duration (also for t < 0),
 * or null while its length is unknown.
 */
export function timelinePosition(time: number, duration: number): number | null {
  if (!(Number.isFinite(duration) && duration > 0 && Number.isFinite(time))) return null;
  return ((time % duration) + duration) % duration;
}

/** How long an export waits for one video to seek before drawing it as it stands. */
const SEEK_WAIT_MS = 3000;

/** Sets the video to `t` seconds and resolves when it shows that frame (or after SEEK_WAIT_MS). */
function seekTo(video: HTMLVideoElement, t: number): Promise<void> {
  const there = Math.abs(video.currentTime - t) < 1e-6 && !video.seeking;
  if (there && video.readyState >= HTMLMediaElement.HAVE_CURRENT_DATA) return Promise.resolve();
  return new Promise<void>((resolve) => {
    const done = () => {
      clearTimeout(timer);
      video.removeEventListener('seeked', done);
      resolve();
    };
    const timer = setTimeout(done, SEEK_WAIT_MS);
    video.addEventListener('seeked', done);
    video.currentTime = t;
  });
}

/**
 * A WebM from a browser's MediaRecorder has no duration (Infinity) until it was read to the end:
 * a seek far past the end makes the browser find it, then playback goes on from the start.
 */
async function knowDuration(video: HTMLVideoElement): Promise<void> {
  if (Number.isFinite(video.duration)) return;
  const found = new Promise<void>((resolve) => {
    const check = () => {
      if (!Number.isFinite(video.duration)) return;
      video.removeEventListener('durationchange', check);
      resolve();
    };
    video.addEventListener('durationchange', check);
  });
  video.currentTime = Number.MAX_SAFE_INTEGER;
  await Promise.race([found, new Promise((r) => setTimeout(r, 2000))]);
  video.currentTime = 0;
}

function newVideo(): HTMLVideoElement {
  const video = document.createElement('video');
  video.muted = true; // autoplay needs it, and a kaleidoscope has no use for sound
  video.loop = true;
  video.playsInline = true;
  return video;
}

/** A sentence for why getUserMedia refused. */
function cameraReason(e: unknown): string {
  const name = e instanceof DOMException ? e.name : '';
  if (name === 'NotAllowedError' || name === 'SecurityError') return 'permission was denied';
  if (name === 'NotFoundError' || name === 'OverconstrainedError') return 'no camera was found';
  if (name === 'NotReadableError') return 'the camera is in use by another program';
  return e instanceof Error ? e.message : String(e);
}

/** The one set of live media of this page (the camera is one device; videos are per node). */
export const liveMedia = new LiveMedia();
