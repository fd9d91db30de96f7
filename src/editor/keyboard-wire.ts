/**
 * Wiring without a pointer: Enter (or Space) on a focused port picks it up, Enter on a compatible
 * port of another node lays the wire (one undo step, the same rules as a drag), Escape or Enter on
 * the same port drops it. Ports are reached with Tab like any control. What happens is said in the
 * live region, since the focus does not move and nothing else would tell a screen-reader user.
 */
import type { Connection } from '@xyflow/react';
import {
  createContext,
  type KeyboardEvent,
  useCallback,
  useContext,
  useEffect,
  useMemo,
  useState,
} from 'react';
import { announce } from '../ui/announce.ts';
import { inHandle, outHandle } from './connection.ts';

export interface PortRef {
  readonly nodeId: string;
  readonly side: 'in' | 'out';
  readonly port: string;
  /** What the port is called in speech: "Line a input". */
  readonly name: string;
}

export interface KeyboardWire {
  /** The port picked up, waiting for its other end. */
  readonly pending: PortRef | null;
  onPortKey(port: PortRef, e: KeyboardEvent): void;
}

export const KeyboardWireContext = createContext<KeyboardWire>({ pending: null, onPortKey() {} });

export const useKeyboardWireContext = () => useContext(KeyboardWireContext);

const samePort = (a: PortRef, b: PortRef) => a.nodeId === b.nodeId && a.side === b.side && a.port === b.port;

/** The connection from `a` to `b` whichever end was picked first (outputs are sources). */
function connectionOf(a: PortRef, b: PortRef): Connection {
  const [from, to] = a.side === 'out' ? [a, b] : [b, a];
  return {
    source: from.nodeId,
    sourceHandle: outHandle(from.port),
    target: to.nodeId,
    targetHandle: inHandle(to.port),
  };
}

/**
 * The keyboard wire state. `check` says why a wire may not be drawn (then nothing changes and the
 * reason is announced); `connect` lays a valid one.
 */
export function useKeyboardWire(
  check: (c: Connection) => { ok: true } | { ok: false; reason: string },
  connect: (c: Connection) => void,
): KeyboardWire {
  const [pending, setPending] = useState<PortRef | null>(null);

  // Escape anywhere drops a picked-up wire (the focus may have moved on with Tab).
  useEffect(() => {
    if (!pending) return;
    const onKey = (e: globalThis.KeyboardEvent) => {
      if (e.key !== 'Escape') return;
      setPending(null);
      announce('Wire cancelled');
    };
    window.addEventListener('keydown', onKey);
    return () => window.removeEventListener('keydown', onKey);
  }, [pending]);

  const onPortKey = useCallback(
    (port: PortRef, e: KeyboardEvent) => {
      if (e.key !== 'Enter' && e.key !== ' ') return;
      // The port's keys are its own: not the node's (select) nor the editor's (palette, open group).
      e.preventDefault();
      e.stopPropagation();
      if (!pending) {
        setPending(port);
        announce(
          `${port.name} picked up: Tab to a ${port.side === 'out' ? 'input' : 'output'} and press Enter`,
        );
        return;
      }
      if (samePort(pending, port)) {
        setPending(null);
        announce('Wire cancelled');
        return;
      }
      if (pending.side === port.side) {
        announce(
          `Both are ${port.side === 'out' ? 'outputs' : 'inputs'}: choose an ${pending.side === 'out' ? 'input' : 'output'}`,
        );
        return;
      }
      const c = connectionOf(pending, port);
      const verdict = check(c);
      if (!verdict.ok) {
        announce(`Cannot connect: ${verdict.reason}`);
        return;
      }
      connect(c);
      setPending(null);
      const [from, to] = pending.side === 'out' ? [pending, port] : [port, pending];
      announce(`Connected ${from.name} to ${to.name}`);
    },
    [pending, check, connect],
  );

  return useMemo(() => ({ pending, onPortKey }), [pending, onPortKey]);
}
