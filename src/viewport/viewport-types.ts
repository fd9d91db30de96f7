/** The Viewport's public option and result types (viewport.ts), the contract the editor uses. */
import type { Diagnostic } from '../../nodes/core/diagnostics.ts';
import type { Camera3d } from '../../nodes/core/scene-3d.ts';
import type { View } from '../../nodes/core/view.ts';
import type { Drawable } from './drawable.ts';

export interface ViewportOptions {
  /** The compiler's and the driver's diagnostics (KF403 with node ids), whenever they change; [] when clean. */
  onDiagnostics?(d: Diagnostic[]): void;
  /**
   * After each drawn frame: samples on screen, the scene's target, and ms since the previous frame
   * (for the first sample: since the edit), which includes waiting for the GPU; `scale` < 1 marks a
   * 3D preview drawn at reduced resolution while the picture changes (its samples count as 0).
   */
  onFrame?(info: { samples: number; target: number; ms: number; scale: number }): void;
  /**
   * After each band of a slow full-size 3D sample is shown but the last (which ends a frame): rows
   * drawn from the top, of how many, and the full-size samples before this one (0: it is drawn over
   * the preview).
   */
  onBand?(info: { rows: number; of: number; samples: number }): void;
  /** Stillness before the baked program is built (default 600; Infinity: never bake). */
  idleBakeMs?: number;
  /**
   * A full-size 3D sample predicted slower than this is drawn in bands of about this long, one per
   * animation frame (frame-bands.ts; default BAND_MS; Infinity: never).
   */
  bandMs?: number;
}

export interface ViewportStats {
  /** Uniform programs compiled (a value edit or a view change never adds one). */
  readonly compiles: number;
  /** Baked programs compiled (idle bake, export): extra, counted apart. */
  readonly bakedCompiles: number;
  /** Frames drawn (each one sample). */
  readonly frames: number;
  /** Samples accumulated in the picture now (0 while it is a reduced preview). */
  readonly samples: number;
  /** Whether the baked program draws now. */
  readonly baked: boolean;
  /** Animation frames that brought a new camera or video frame (live-textures.ts). */
  readonly liveUploads: number;
  /** The scale (each side) the picture on screen was drawn at: < 1 for a 3D preview while it changes. */
  readonly renderScale: number;
  /** The pixel size the picture on screen was drawn at (the canvas's, times renderScale). */
  readonly renderSize: { readonly width: number; readonly height: number };
  /** The 3D pane's scale for interactive frames, from the measured frame times (render-scale.ts). */
  readonly interactiveScale: number;
  /** The bands the last full sample was drawn in (1: in one draw; frame-bands.ts). */
  readonly bands: number;
  /** The full-size sample being drawn in bands now: bands and rows shown (from the top), of its rows. */
  readonly band: { readonly bands: number; readonly rows: number; readonly of: number } | null;
}

export interface RenderToPixelsOptions {
  width: number;
  height: number;
  samples: number;
  view?: View;
  /** The camera of a 3D scene (default: the live view's). */
  camera?: Camera3d;
  transparent?: boolean;
  /** Fraction done in [0, 1]; return false to cancel. */
  // biome-ignore lint/suspicious/noConfusingVoidType: the editor's API (a callback may return nothing)
  onProgress?(f: number): boolean | void;
  tile?: number;
  /**
   * The scene to draw instead of the live one (e.g. with edge widths scaled for a larger export).
   * `view` applies to a 2D scene, `camera` to a 3D one.
   */
  scene?: Drawable;
}
