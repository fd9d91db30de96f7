/** The one-click repair offered with a diagnostic (its `fix`), wherever the diagnostic is shown. */
import type { Diagnostic, DiagnosticFix } from '../../nodes/core/diagnostics.ts';

/** The distinct fixes among some diagnostics (several warnings may offer the same one). */
export function distinctFixes(diagnostics: readonly Diagnostic[]): DiagnosticFix[] {
  const seen = new Map<string, DiagnosticFix>();
  for (const d of diagnostics) if (d.fix && !seen.has(d.fix.label)) seen.set(d.fix.label, d.fix);
  return [...seen.values()];
}

export function FixButton({ fix, onFix }: { fix: DiagnosticFix; onFix(fix: DiagnosticFix): void }) {
  return (
    // nodrag: a click on the button inside a graph node must not start moving the node.
    <button
      type="button"
      className="kf-fix nodrag"
      onClick={() => onFix(fix)}
      title={`${fix.label} (one undo step)`}
    >
      {fix.label}
    </button>
  );
}
