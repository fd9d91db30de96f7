/**
 * Help: the one-minute quick starts (2D and 3D), the guided walkthrough, a few examples to open,
 * what the socket colours mean, and the keyboard shortcuts.
 */

import { PORT_TYPE_INFO, PORT_TYPES } from '../../../nodes/core/ports.ts';
import type { Example } from '../examples.ts';
import { SHORTCUTS } from '../shortcuts.ts';
import { useModalDialog } from '../use-modal-dialog.ts';
import { FormulaHelp } from './FormulaHelp.tsx';
import { QUICK_START, QUICK_START_3D, type QuickStep } from './quick-start.ts';

/** Examples worth opening first, by id (a missing one is skipped). */
const STARTER_EXAMPLES = [
  'kaleidoscope-333',
  'hyperbolic-237',
  'apollonian-gasket',
  'schottky-pair',
  'loxodromic-spiral',
  'fig26-quasi-sphere',
];

interface Props {
  readonly examples: readonly Example[];
  onExample(example: Example): void;
  onWalkthrough(): void;
  onClose(): void;
}

function Steps({ steps }: { readonly steps: readonly QuickStep[] }) {
  return (
    <ol className="kf-help__steps">
      {steps.map((s) => (
        <li key={s.title}>
          <strong>{s.title}.</strong> {s.detail}
        </li>
      ))}
    </ol>
  );
}

export function HelpDialog({ examples, onExample, onWalkthrough, onClose }: Props) {
  const dialog = useModalDialog(onClose);
  const starters = STARTER_EXAMPLES.flatMap((id) => examples.filter((e) => e.id === id));
  return (
    <dialog ref={dialog.ref} className="kf-dialog kf-help" aria-label="Help" onClose={dialog.onClose}>
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

      <section aria-labelledby="kf-help-quick">
        <h3 id="kf-help-quick">Your first kaleidoscope in five steps</h3>
        <Steps steps={QUICK_START} />
        <button type="button" className="kf-button" onClick={onWalkthrough}>
          Build a kaleidoscope from points, step by step
        </button>
      </section>

      <section aria-labelledby="kf-help-quick-3d">
        <h3 id="kf-help-quick-3d">Your first 3D picture in four steps</h3>
        <Steps steps={QUICK_START_3D} />
      </section>

      {starters.length > 0 && (
        <section aria-labelledby="kf-help-examples">
          <h3 id="kf-help-examples">Examples to open</h3>
          <ul className="kf-help__examples">
            {starters.map((e) => (
              <li key={e.id}>
                <button type="button" className="kf-link" onClick={() => onExample(e)}>
                  {e.title}
                </button>
              </li>
            ))}
          </ul>
          <p className="kf-dialog__foot">All of them are under Examples in the top bar.</p>
        </section>
      )}

      <section aria-labelledby="kf-help-sockets">
        <h3 id="kf-help-sockets">Socket colours</h3>
        <p className="kf-dialog__foot">A wire joins an output to an input of the same colour.</p>
        <ul className="kf-help__sockets">
          {PORT_TYPES.map((t) => (
            <li key={t}>
              <span className="kf-help__swatch" style={{ background: PORT_TYPE_INFO[t].color }} aria-hidden />
              <strong>{t}</strong> — {PORT_TYPE_INFO[t].doc}
            </li>
          ))}
        </ul>
      </section>

      <FormulaHelp />

      <section aria-labelledby="kf-help-keys">
        <h3 id="kf-help-keys">Keyboard shortcuts</h3>
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
      </section>
      <p className="kf-dialog__foot">On a Mac, Ctrl is ⌘. Your graph is saved in this browser as you work.</p>
    </dialog>
  );
}
