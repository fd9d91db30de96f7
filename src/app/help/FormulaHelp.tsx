/**
 * Help's "Formulas" section: what the Formula node's text may hold, read from the language's own
 * tables (nodes/formula/functions.ts, the node's names), so it cannot drift from what is accepted.
 */
import { CONSTANTS, FUNCTIONS } from '../../../nodes/formula/functions.ts';
import { FORMULA_NAMES } from '../../../nodes/formula/names.ts';

const forms = (name: string) =>
  FUNCTIONS[name]!.signatures.map((s) => `${name}(${s.args.join(', ')}${s.repeats ? ', …' : ''})`).join(
    ' · ',
  );

export function FormulaHelp() {
  return (
    <section aria-labelledby="kf-help-formulas">
      <h3 id="kf-help-formulas">Formulas</h3>
      <p className="kf-dialog__foot">
        The Formula node computes a number or a point from its inputs{' '}
        {Object.keys(FORMULA_NAMES).map((n, i) => (
          <span key={n}>
            {i > 0 && ', '}
            <code>{n}</code>
          </span>
        ))}{' '}
        (t is the animation time) and the constants{' '}
        {Object.keys(CONSTANTS).map((n, i) => (
          <span key={n}>
            {i > 0 && ', '}
            <code>{n}</code>
          </span>
        ))}
        . Write <code>+ - * / %</code>, <code>**</code> for a power, brackets, comparisons{' '}
        <code>{'< <= > >= == !='}</code> joined by <code>{'&& || !'}</code> inside{' '}
        <code>test ? this : that</code>, and <code>p.x</code>, <code>p.y</code>. A mistake is shown on the
        node with the characters at fault. Example: <code>rotate(q - p, pi / a) + p</code>.
      </p>
      <ul className="kf-help__functions">
        {Object.entries(FUNCTIONS).map(([name, fn]) => (
          <li key={name}>
            <code>{forms(name)}</code> — {fn.doc}
          </li>
        ))}
      </ul>
    </section>
  );
}
