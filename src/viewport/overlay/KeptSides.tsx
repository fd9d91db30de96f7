/** Draws kept-side-shapes.ts: each mirror's hatched back, and the hovered mirror's discarded side. */

import { BAND_PX, type KeptSideShape } from './kept-side-shapes.ts';

const points = (ps: readonly (readonly number[])[]) => ps.map((p) => `${p[0]},${p[1]}`).join(' ');

export function KeptSides(props: {
  shapes: readonly KeptSideShape[];
  colorOf(nodeId: string): string;
  hoveredNodeIds: ReadonlySet<string>;
}) {
  const colors = [...new Set(props.shapes.map((s) => props.colorOf(s.nodeId)))];
  const hatch = (color: string) => `url(#kf-hatch-${colors.indexOf(color)})`;
  return (
    <g className="kf-kept-sides" pointerEvents="none" data-testid="kept-sides">
      <defs>
        {colors.map((color, i) => (
          <pattern
            key={color}
            id={`kf-hatch-${i}`}
            width={6}
            height={6}
            patternUnits="userSpaceOnUse"
            patternTransform="rotate(45)"
          >
            {/* A dark stroke under the colour: the hatching shows on any picture, pink on pink too. */}
            <line x1={1.5} y1={0} x2={1.5} y2={6} stroke="#000000" strokeWidth={3} opacity={0.55} />
            <line x1={1.5} y1={0} x2={1.5} y2={6} stroke={color} strokeWidth={1.5} />
          </pattern>
        ))}
      </defs>
      {props.shapes.map((s, i) => {
        const color = props.colorOf(s.nodeId);
        const hot = props.hoveredNodeIds.has(s.nodeId);
        if (s.kind === 'circle') {
          // The back of a circle mirror is its inside (its outside when it keeps the inside): a
          // hatched ring just within (beyond) the rim. The hovered one shades its back: the disk,
          // or everything but the disk (an even-odd path: the pane with the disk cut out).
          const ring = s.keepInside ? s.r + BAND_PX / 2 : s.r - BAND_PX / 2;
          const disk = `M${s.c[0] - s.r},${s.c[1]}a${s.r},${s.r} 0 1,0 ${2 * s.r},0a${s.r},${s.r} 0 1,0 ${-2 * s.r},0`;
          const back = s.keepInside ? `M-1e5,-1e5H1e5V1e5H-1e5Z${disk}` : disk;
          return (
            // biome-ignore lint/suspicious/noArrayIndexKey: one node may make several mirrors
            <g key={i} data-kept-side={s.nodeId}>
              {hot && <path d={back} fillRule="evenodd" fill={color} opacity={0.15} />}
              {ring > BAND_PX / 2 && (
                <circle
                  cx={s.c[0]}
                  cy={s.c[1]}
                  r={ring}
                  fill="none"
                  stroke={hatch(color)}
                  strokeWidth={BAND_PX}
                />
              )}
            </g>
          );
        }
        return (
          // biome-ignore lint/suspicious/noArrayIndexKey: one node may make several mirrors
          <g key={i} data-kept-side={s.nodeId}>
            {hot && s.discarded.length >= 3 && (
              <polygon points={points(s.discarded)} fill={color} opacity={0.15} />
            )}
            <polygon points={points(s.band)} fill={hatch(color)} />
          </g>
        );
      })}
    </g>
  );
}
