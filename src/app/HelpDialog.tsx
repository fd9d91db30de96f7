/** Help: what Kleinflow is in two lines, and the keyboard shortcuts table. */
import { useEffect, useRef } from 'react';
import { SHORTCUTS } from './shortcuts.ts';

export function HelpDialog({ onClose }: { onClose(): void }) {
  const ref = useRef<HTMLDialogElement>(null);
  useEffect(() => {
    const d = ref.current!;
    if (!d.open) d.showModal();
    return () => d.close();
  }, []);
  return (
    <dialog ref={ref} className="kf-dialog" aria-label="Help" onClose={onClose} onCancel={onClose}>
      <header className="kf-dialog__header">
        <h2>Kleinflow</h2>
        <button type="button" className="kf-icon-button" aria-label="Close help" onClick={onClose}>
          ×
        </button>
      </header>
      <p className="kf-dialog__lead">
        Wire points, lines and circles into mirrors and Möbius generators; the Render node turns them into an
        Iterated Inversion System, drawn live on the right. Drag the handles in the picture and the tiling
        follows.
      </p>
      <div className="kf-shortcuts">
        {SHORTCUTS.map((g) => (
          <table key={g.group} className="kf-shortcuts__table">
            <caption>{g.group}</caption>
            <tbody>
              {g.items.map((s) => (
                <tr key={s.action}>
                  <td>
                    {s.keys.map((k, i) => (
                      <span key={k}>
                        {i > 0 && <span className="kf-shortcuts__or"> or </span>}
                        <kbd>{k}</kbd>
                      </span>
                    ))}
                  </td>
                  <td>{s.action}</td>
                </tr>
              ))}
            </tbody>
          </table>
        ))}
      </div>
      <p className="kf-dialog__foot">On a Mac, Ctrl is ⌘. Your graph is saved in this browser as you work.</p>
    </dialog>
  );
}
