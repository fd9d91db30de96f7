/**
 * The sphairahedron's parameter space in its inspector (paper Fig. 30, the small panel with the
 * current parameter as a red point): the (zb, zc) plane — the zb axis for types with zb only —
 * painted by what the shape is there (valid, bridge, tunnel, both, no shape), the class
 * boundaries drawn, the current parameter marked. A click sets zb, zc in one undo step, a drag
 * pans, the arrow keys step the parameter. Classes: docs/math-3d.md "The parameter space: bridges
 * and tunnels".
 */
import { type KeyboardEvent, type PointerEvent, useEffect, useMemo, useRef, useState } from 'react';
import { SPACE_CLASSES, type SpaceClass } from '../../nodes/geometry/space/sphairahedron-space.ts';
import { spaceGrid } from '../../nodes/geometry/space/sphairahedron-space-grid.ts';
import {
  SPHAIRAHEDRON_TYPE_IDS,
  sphairahedronTypeById,
} from '../../nodes/geometry/space/sphairahedron-types.ts';
import type { GraphNode } from '../../nodes/graph/document.ts';
import { useStore } from '../state/use-store.ts';

const SIDE = 240;
/** Cells per side: each builds a shape (about a millisecond), so the grid stays small. */
const CELLS = 48;
const STRIP = 36;
const HALF = 2.5;

const COLOURS: Record<SpaceClass, string> = {
  valid: '#5fb86a',
  bridge: '#4a90d9',
  tunnel: '#e3963e',
  'bridge-tunnel': '#a465c8',
  degenerate: '#2b2b30',
};
const NAMES: Record<SpaceClass, string> = {
  valid: 'valid (a sphairahedron of the type)',
  bridge: 'bridges',
  tunnel: 'tunnels',
  'bridge-tunnel': 'bridges and tunnels',
  degenerate: 'no shape (a radius ≤ 0)',
};

const round = (v: number) => Math.round(v * 100) / 100;

export function SphairahedronSpaceSection({ node }: { node: GraphNode }) {
  const store = useStore();
  const canvas = useRef<HTMLCanvasElement>(null);
  const [center, setCenter] = useState<readonly [number, number]>([0, 0]);
  const drag = useRef<{ x: number; y: number; moved: boolean; center: readonly [number, number] } | null>(
    null,
  );
  // An unset type is the node's default, the first of the table (cube A).
  const type =
    node.type === 'sphairahedron'
      ? sphairahedronTypeById(String(node.params.shape ?? SPHAIRAHEDRON_TYPE_IDS[0]))
      : undefined;
  const twoD = type?.kind === 'cube';
  const rows = twoD ? CELLS : 1;
  const height = twoD ? SIDE : STRIP;
  const zb = Number(node.params.zb ?? 0);
  const zc = twoD ? Number(node.params.zc ?? 0) : 0;
  const grid = useMemo(
    () => (type ? spaceGrid(type, { center, half: HALF }, CELLS, rows) : null),
    [type, center, rows],
  );
  const unit = SIDE / (2 * HALF);
  const toScreen = (b: number, c: number): [number, number] => [
    (b - center[0] + HALF) * unit,
    twoD ? (center[1] + HALF - c) * unit : height / 2,
  ];
  const here: SpaceClass = useMemo(() => {
    if (!type || !grid) return 'degenerate';
    const i = Math.floor(((zb - center[0] + HALF) / (2 * HALF)) * CELLS);
    const j = twoD ? Math.floor(((center[1] + HALF - zc) / (2 * HALF)) * CELLS) : 0;
    return i >= 0 && i < CELLS && j >= 0 && j < rows ? SPACE_CLASSES[grid[j * CELLS + i]!]! : 'degenerate';
  }, [type, grid, zb, zc, center, twoD, rows]);

  useEffect(() => {
    const ctx = canvas.current?.getContext('2d');
    if (!ctx || !grid) return;
    const cw = SIDE / CELLS;
    const ch = height / rows;
    for (let j = 0; j < rows; j++)
      for (let i = 0; i < CELLS; i++) {
        ctx.fillStyle = COLOURS[SPACE_CLASSES[grid[j * CELLS + i]!]!];
        ctx.fillRect(i * cw, j * ch, cw + 0.5, ch + 0.5);
      }
    // The boundary: an edge between two cells of different classes.
    ctx.strokeStyle = '#f4f4f4';
    ctx.lineWidth = 1.5;
    ctx.beginPath();
    for (let j = 0; j < rows; j++)
      for (let i = 0; i < CELLS; i++) {
        const k = grid[j * CELLS + i];
        if (i + 1 < CELLS && grid[j * CELLS + i + 1] !== k) {
          ctx.moveTo((i + 1) * cw, j * ch);
          ctx.lineTo((i + 1) * cw, (j + 1) * ch);
        }
        if (j + 1 < rows && grid[(j + 1) * CELLS + i] !== k) {
          ctx.moveTo(i * cw, (j + 1) * ch);
          ctx.lineTo((i + 1) * cw, (j + 1) * ch);
        }
      }
    ctx.stroke();
    const [x, y] = toScreen(zb, zc);
    ctx.fillStyle = '#e53935';
    ctx.strokeStyle = '#ffffff';
    ctx.beginPath();
    ctx.arc(x, y, 5, 0, 2 * Math.PI);
    ctx.fill();
    ctx.stroke();
  });

  if (!type) return null;

  const set = (b: number, c: number) =>
    store.dispatch(
      {
        type: 'set-params',
        patches: [{ nodeId: node.id, params: twoD ? { zb: round(b), zc: round(c) } : { zb: round(b) } }],
      },
      'choose (zb, zc) in the parameter space',
    );
  const down = (e: PointerEvent<HTMLCanvasElement>) => {
    e.currentTarget.setPointerCapture?.(e.pointerId);
    drag.current = { x: e.clientX, y: e.clientY, moved: false, center };
  };
  const move = (e: PointerEvent<HTMLCanvasElement>) => {
    const d = drag.current;
    if (!d) return;
    const dx = e.clientX - d.x;
    const dy = e.clientY - d.y;
    if (!d.moved && Math.hypot(dx, dy) < 4) return;
    d.moved = true;
    setCenter([round(d.center[0] - dx / unit), twoD ? round(d.center[1] + dy / unit) : 0]);
  };
  const up = (e: PointerEvent<HTMLCanvasElement>) => {
    const d = drag.current;
    drag.current = null;
    if (!d || d.moved) return;
    const r = e.currentTarget.getBoundingClientRect();
    const x = ((e.clientX - r.left) / r.width) * SIDE;
    const y = ((e.clientY - r.top) / r.height) * height;
    set(center[0] - HALF + x / unit, twoD ? center[1] + HALF - y / unit : zc);
  };
  const key = (e: KeyboardEvent<HTMLCanvasElement>) => {
    const step = e.shiftKey ? 0.2 : 0.05;
    const moves: Record<string, [number, number]> = {
      ArrowLeft: [-step, 0],
      ArrowRight: [step, 0],
      ArrowUp: twoD ? [0, step] : [0, 0],
      ArrowDown: twoD ? [0, -step] : [0, 0],
    };
    const m = moves[e.key];
    if (!m || (m[0] === 0 && m[1] === 0)) return;
    e.preventDefault();
    set(zb + m[0], zc + m[1]);
  };

  const where = twoD ? `(zb, zc) = (${round(zb)}, ${round(zc)})` : `zb = ${round(zb)}`;
  return (
    <>
      <h3>Parameter space</h3>
      <canvas
        ref={canvas}
        width={SIDE}
        height={height}
        className="kf-space-view"
        style={{ width: SIDE, height, touchAction: 'none', cursor: 'crosshair' }}
        tabIndex={0}
        role="slider"
        aria-valuenow={round(zb)}
        aria-valuemin={round(center[0] - HALF)}
        aria-valuemax={round(center[0] + HALF)}
        aria-valuetext={`${where}: ${NAMES[here]}`}
        aria-label={`Parameter space of ${type.label}: ${where}, ${NAMES[here]}. Click to choose, drag to pan, arrow keys step the parameter (Shift: larger steps)`}
        data-testid="sphairahedron-space"
        onPointerDown={down}
        onPointerMove={move}
        onPointerUp={up}
        onKeyDown={key}
      />
      <p className="kf-inspector__hint" role="status" data-testid="sphairahedron-space-status">
        {where}: {NAMES[here]}. Shown: zb {round(center[0] - HALF)} … {round(center[0] + HALF)}
        {twoD ? `, zc ${round(center[1] - HALF)} … ${round(center[1] + HALF)}` : ' (this type has zb only)'}.
      </p>
      <ul className="kf-inspector__hint" aria-label="Legend">
        {SPACE_CLASSES.map((c) => (
          <li key={c}>
            <span aria-hidden="true" style={{ color: COLOURS[c] }}>
              ■{' '}
            </span>
            {NAMES[c]}
          </li>
        ))}
      </ul>
    </>
  );
}
