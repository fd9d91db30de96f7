/**
 * The render node's figures (Cayley graph, depth-first limit set: shader-gen/figures/layer.ts)
 * over the picture, in CSS pixels at the live view: the same layer the SVG and PNG exports draw
 * (at the document's view, which the live view is stored into once it rests).
 * Not interactive (pointer events pass through to the handles and the pan/zoom).
 */
import { type JSX, useMemo } from 'react';
import type { Scene } from '../../../nodes/core/scene.ts';
import { figureLayer } from '../../../shader-gen/figures/layer.ts';
import { hexColour } from '../../../shader-gen/vector/svg.ts';
import { type Screen, toCss } from './screen.ts';

export function FigureOverlay(props: { scene: Scene; screen: Screen }): JSX.Element | null {
  const { scene, screen } = props;
  const layer = useMemo(
    // The base point of the Cayley graph from the document's view: it stays put while this view
    // pans (the document's view follows once the pan rests, as the exports see it).
    () => figureLayer({ ...scene, view: screen.view }, screen.width, screen.height, scene.view),
    [scene, screen],
  );
  if (layer.strokes.length + layer.dots.length + layer.notes.length === 0) return null;
  const css = (p: readonly [number, number]) => toCss(screen, p);
  return (
    <g className="kf-figures" pointerEvents="none" data-testid="figure-overlay">
      {layer.strokes.map((s, i) => (
        <polyline
          // biome-ignore lint/suspicious/noArrayIndexKey: the layer is rebuilt whole, never reordered
          key={`s${i}`}
          points={s.points.map((p) => css(p).join(',')).join(' ')}
          fill="none"
          stroke={hexColour(s.color)}
          strokeWidth={s.width}
          strokeLinecap="round"
          strokeLinejoin="round"
        />
      ))}
      {layer.dots.map((d, i) => {
        const [x, y] = css(d.at);
        // biome-ignore lint/suspicious/noArrayIndexKey: as above
        return <circle key={`d${i}`} cx={x} cy={y} r={d.r} fill={hexColour(d.color)} />;
      })}
      {layer.labels.map((l, i) => {
        const [x, y] = css(l.at);
        return (
          <text
            // biome-ignore lint/suspicious/noArrayIndexKey: as above
            key={`l${i}`}
            x={x + 4}
            y={y - 4}
            fill={hexColour(l.color)}
            fontSize={14}
            fontWeight="bold"
            stroke="#000000"
            strokeWidth={3}
            paintOrder="stroke"
          >
            {l.text}
          </text>
        );
      })}
      {layer.notes.map((n, i) => (
        <text
          key={n}
          x={8}
          y={screen.height - 10 - 18 * i}
          fill="#ffcc66"
          fontSize={12}
          stroke="#000000"
          strokeWidth={3}
          paintOrder="stroke"
          data-testid="figure-note"
        >
          {n}
        </text>
      ))}
    </g>
  );
}
