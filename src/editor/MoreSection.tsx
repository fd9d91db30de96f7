/**
 * A node's collapsible "More" section for its rarely used settings. Whether it is open is UI
 * state, never saved in the document: remembered per node id for this page's lifetime, so it
 * survives the node component being unmounted and mounted again (panning, undo).
 */
import { type ReactNode, useCallback, useState } from 'react';

const openByNode = new Map<string, boolean>();

function useMoreOpen(nodeId: string): [boolean, (open: boolean) => void] {
  const [open, setOpen] = useState(() => openByNode.get(nodeId) ?? false);
  const set = useCallback(
    (v: boolean) => {
      openByNode.set(nodeId, v);
      setOpen(v);
    },
    [nodeId],
  );
  return [open, set];
}

export function MoreSection({
  nodeId,
  count,
  children,
}: {
  nodeId: string;
  count: number;
  children: ReactNode;
}) {
  const [open, setOpen] = useMoreOpen(nodeId);
  return (
    <div className={`kf-more${open ? ' kf-more--open' : ''}`}>
      <button
        type="button"
        className="kf-more__toggle nodrag"
        aria-expanded={open}
        title={open ? 'Hide the rarely used settings' : `Show ${count} more setting${count === 1 ? '' : 's'}`}
        onClick={() => setOpen(!open)}
      >
        <span className="kf-more__chevron" aria-hidden="true" />
        {open ? 'less' : 'more'}
        {!open && <span className="kf-more__count">{count}</span>}
      </button>
      {open && children}
    </div>
  );
}
