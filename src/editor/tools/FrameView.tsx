/**
 * A frame on the canvas (a React Flow node of type "frame", drawn behind the graph's nodes): a
 * title and colour you can edit, resizable when selected. Only its title bar catches the pointer
 * (dragging it moves the frame and its nodes, GraphEditor); the body lets clicks through to the
 * canvas and the nodes on it.
 */
import { type Node, type NodeProps, NodeResizer } from '@xyflow/react';
import { memo, useEffect, useState } from 'react';
import type { GraphFrame } from '../../../nodes/graph/document.ts';
import type { Change } from '../../state/changes.ts';
import { useStore } from '../../state/use-store.ts';
import { gridPosition } from '../new-node.ts';

export type FrameNode = Node<{ frame: GraphFrame }, 'frame'>;

/** React Flow ids of frames, apart from node ids. */
export const FRAME_PREFIX = 'frame:';
export const isFrameId = (id: string): boolean => id.startsWith(FRAME_PREFIX);

export function toFrameNodes(frames: readonly GraphFrame[], selected: ReadonlySet<string>): FrameNode[] {
  return frames.map((frame) => ({
    id: FRAME_PREFIX + frame.id,
    type: 'frame',
    position: { x: frame.position[0], y: frame.position[1] },
    width: frame.size[0],
    height: frame.size[1],
    zIndex: -1,
    dragHandle: '.kf-frame__header',
    selected: selected.has(FRAME_PREFIX + frame.id),
    style: { pointerEvents: 'none' },
    data: { frame },
  }));
}

function FrameViewImpl({ data: { frame }, selected }: NodeProps<FrameNode>) {
  const store = useStore();
  const [title, setTitle] = useState(frame.title);
  useEffect(() => setTitle(frame.title), [frame.title]);
  const put = (next: GraphFrame, label: string) => {
    const change: Change = { type: 'put-frame', frame: next };
    store.dispatch(change, label);
  };
  return (
    <section
      className="kf-frame"
      style={{ '--kf-frame': frame.color } as React.CSSProperties}
      aria-label={`Frame ${frame.title}`}
    >
      <NodeResizer
        isVisible={selected}
        minWidth={120}
        minHeight={80}
        onResizeEnd={(_e, p) =>
          put(
            {
              ...frame,
              position: gridPosition(p.x, p.y),
              size: [Math.max(1, Math.round(p.width)), Math.max(1, Math.round(p.height))],
            },
            'resize frame',
          )
        }
      />
      <header className="kf-frame__header">
        <span className="kf-frame__grip" title="Drag to move the frame and the nodes in it">
          ⠿
        </span>
        <input
          className="kf-frame__title nodrag"
          aria-label="Frame title"
          value={title}
          onChange={(e) => setTitle(e.target.value)}
          onBlur={() =>
            title !== frame.title && put({ ...frame, title: title.slice(0, 200) }, 'rename frame')
          }
          onKeyDown={(e) => e.key === 'Enter' && (e.target as HTMLInputElement).blur()}
        />
        <input
          type="color"
          className="kf-frame__colour nodrag"
          aria-label="Frame colour"
          value={frame.color}
          onChange={(e) => put({ ...frame, color: e.target.value }, 'frame colour')}
        />
      </header>
    </section>
  );
}

export const FrameView = memo(FrameViewImpl);
