/**
 * What the graph editor does for keyboard and screen-reader users beyond React Flow's own node
 * focus: wiring from the keyboard (keyboard-wire.ts), the focus landing on a node just added (the
 * palette that had it is gone), and new warnings and errors said in the live region.
 */
import type { Connection } from '@xyflow/react';
import { type RefObject, useEffect, useRef } from 'react';
import type { Diagnostic } from '../../nodes/core/diagnostics.ts';
import type { NodeRegistry } from '../../nodes/core/registry.ts';
import type { GraphDoc } from '../../nodes/graph/document.ts';
import { nodeDef } from '../../nodes/graph/group-def.ts';
import { announce } from '../ui/announce.ts';
import { checkConnection } from './connection.ts';
import { type KeyboardWire, useKeyboardWire } from './keyboard-wire.ts';

interface Inputs {
  readonly doc: GraphDoc;
  readonly getDoc: () => GraphDoc;
  readonly registry: NodeRegistry;
  readonly selection: ReadonlySet<string>;
  readonly diagnostics: readonly Diagnostic[];
  readonly onConnect: (c: Connection) => void;
  readonly wrapper: RefObject<HTMLDivElement | null>;
}

/** More new problems than this at once (a file opened) are summed up, not read one by one. */
const MAX_READ_OUT = 3;
/** Frames to wait for a new node to be drawn before giving up focusing it. */
const FOCUS_FRAMES = 10;

const nodeName = (doc: GraphDoc, registry: NodeRegistry, id: string | undefined) => {
  const node = id ? doc.nodes.find((n) => n.id === id) : undefined;
  return node ? (node.label ?? nodeDef(registry, node)?.label ?? node.type) : undefined;
};

const keyOf = (d: Diagnostic) => `${d.severity}|${d.code}|${d.nodeId ?? ''}|${d.port ?? ''}|${d.message}`;

export function useGraphA11y(o: Inputs): KeyboardWire {
  const { doc, getDoc, registry, selection, diagnostics, onConnect, wrapper } = o;
  const wire = useKeyboardWire((c) => checkConnection(getDoc(), registry, c), onConnect);

  // A node added from the palette (or pasted) while the focus fell to the page: focus the node, so
  // Tab goes on into its ports and fields instead of starting over at the top bar. The document
  // and the selection change in two steps, so the ids new in the last document are kept for it.
  const known = useRef<ReadonlySet<string> | null>(null);
  const added = useRef<ReadonlySet<string>>(new Set());
  useEffect(() => {
    const ids = new Set(doc.nodes.map((n) => n.id));
    const before = known.current;
    if (before) added.current = new Set([...ids].filter((id) => !before.has(id)));
    known.current = ids;
  }, [doc]);
  useEffect(() => {
    const [id] = selection;
    if (selection.size !== 1 || !added.current.has(id)) return;
    added.current = new Set();
    let frame = 0;
    let tries = FOCUS_FRAMES;
    const focus = () => {
      const lost = document.activeElement === null || document.activeElement === document.body;
      const el = wrapper.current?.querySelector<HTMLElement>(
        `.react-flow__node[data-id="${CSS.escape(id)}"]`,
      );
      if (!lost) return;
      el?.focus();
      // React Flow shows the node (until then hidden: no focus) a frame or two after the document has it.
      if (document.activeElement !== el && --tries > 0) frame = requestAnimationFrame(focus);
    };
    frame = requestAnimationFrame(focus);
    return () => cancelAnimationFrame(frame);
  }, [selection, wrapper]);

  // New warnings and errors, said once each (the first evaluation is what was opened: not read).
  const said = useRef<ReadonlySet<string> | null>(null);
  useEffect(() => {
    const problems = diagnostics.filter((d) => d.severity !== 'info');
    const before = said.current;
    said.current = new Set(problems.map(keyOf));
    if (!before) return;
    const fresh = problems.filter((d) => !before.has(keyOf(d)));
    if (fresh.length === 0) return;
    if (fresh.length > MAX_READ_OUT) {
      announce(`${fresh.length} new problems`);
      return;
    }
    const doc = getDoc();
    announce(
      fresh
        .map((d) => {
          const where = nodeName(doc, registry, d.nodeId);
          return `${d.severity === 'error' ? 'Error' : 'Warning'}${where ? ` on ${where}` : ''}: ${d.message}`;
        })
        .join('. '),
    );
  }, [diagnostics, getDoc, registry]);

  return wire;
}
