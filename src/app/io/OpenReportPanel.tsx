/** The dismissible panel listing every problem (with its JSON path) or import note after an open. */
import type { OpenReport } from './open-report.ts';

export function OpenReportPanel({ report, onDismiss }: { report: OpenReport; onDismiss(): void }) {
  return (
    <section
      className={`kf-open-report kf-open-report--${report.kind}`}
      role={report.kind === 'error' ? 'alert' : 'status'}
      aria-label="Open report"
      data-testid="open-report"
    >
      <header className="kf-open-report__head">
        <span>{report.title}</span>
        <button type="button" className="kf-icon-button" aria-label="Dismiss" onClick={onDismiss}>
          ×
        </button>
      </header>
      <ol className="kf-open-report__items">
        {report.items.map((it, i) => (
          // biome-ignore lint/suspicious/noArrayIndexKey: the list is replaced whole, never reordered
          <li key={i}>
            <code className="kf-open-report__path">{it.path}</code>
            <span className="kf-open-report__text">{it.text}</span>
            <span className="kf-open-report__code">{it.code}</span>
          </li>
        ))}
      </ol>
    </section>
  );
}
