/** Messages that need the user's attention (an unreadable autosave, full storage, a file that did not load). */
export interface Message {
  readonly id: string;
  readonly kind: 'error' | 'warning' | 'info';
  readonly text: string;
  readonly details?: readonly string[];
  /**
   * Buttons on the message. What `run` returns says what the message becomes once the action is
   * done, so it never goes on saying what is no longer true: a Message replaces it, null removes
   * it, nothing (undefined) leaves it as it is.
   */
  readonly actions?: readonly { label: string; run(): Message | null | undefined }[];
}

export function Banner({
  messages,
  onDismiss,
  onReplace,
}: {
  messages: readonly Message[];
  onDismiss(id: string): void;
  /** The message `id` became `next` after one of its actions ran. */
  onReplace(id: string, next: Message): void;
}) {
  // Always rendered (possibly empty) so the app's grid rows stay in place.
  return (
    <div className="kf-banners">
      {messages.map((m) => (
        <div
          key={m.id}
          className={`kf-banner kf-banner--${m.kind}`}
          role={m.kind === 'error' ? 'alert' : 'status'}
        >
          <div className="kf-banner__text">
            {m.text}
            {m.details && m.details.length > 0 && (
              <ul className="kf-banner__details">
                {m.details.slice(0, 5).map((d) => (
                  <li key={d}>{d}</li>
                ))}
              </ul>
            )}
          </div>
          {m.actions?.map((a) => (
            <button
              key={a.label}
              type="button"
              className="kf-button"
              onClick={() => {
                const next = a.run();
                if (next === null) onDismiss(m.id);
                else if (next) onReplace(m.id, next);
              }}
            >
              {a.label}
            </button>
          ))}
          <button
            type="button"
            className="kf-icon-button"
            aria-label="Dismiss"
            onClick={() => onDismiss(m.id)}
          >
            ×
          </button>
        </div>
      ))}
    </div>
  );
}
