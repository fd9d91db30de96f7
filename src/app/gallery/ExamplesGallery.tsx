/**
 * The Examples gallery: every bundled example as a card (thumbnail, title, one line), grouped,
 * searchable as you type. Enter opens the first match; Escape closes.
 */
import { useEffect, useMemo, useRef, useState } from 'react';
import type { Example } from '../examples.ts';
import { useModalDialog } from '../use-modal-dialog.ts';
import { galleryGroups, oneLine } from './groups.ts';
import { thumbnailUrl } from './thumbnails.ts';

interface Props {
  readonly examples: readonly Example[];
  onOpen(example: Example): void;
  onClose(): void;
}

export function ExamplesGallery({ examples, onOpen, onClose }: Props) {
  const dialog = useModalDialog(onClose);
  const [query, setQuery] = useState('');
  const search = useRef<HTMLInputElement>(null);
  // After showModal (the hook's effect, which runs first) focused the close button: typing searches.
  useEffect(() => search.current?.focus(), []);
  const groups = useMemo(() => galleryGroups(examples, query), [examples, query]);
  const first = groups[0]?.examples[0];
  return (
    <dialog ref={dialog.ref} className="kf-dialog kf-gallery" aria-label="Examples" onClose={dialog.onClose}>
      <header className="kf-dialog__header">
        <h2>Examples</h2>
        <button type="button" className="kf-icon-button" aria-label="Close examples" onClick={onClose}>
          ×
        </button>
      </header>
      <input
        className="kf-input kf-gallery__search"
        type="search"
        ref={search}
        aria-label="Search examples"
        placeholder="Search: kaleidoscope, Schottky, Fig. 13, spiral…"
        value={query}
        onChange={(e) => setQuery(e.target.value)}
        onKeyDown={(e) => {
          if (e.key === 'Enter' && first) onOpen(first);
        }}
      />
      {groups.length === 0 && <p className="kf-dialog__lead">No example matches “{query}”.</p>}
      {groups.map((g) => (
        <section key={g.title} aria-label={g.title}>
          <h3 className="kf-gallery__group">{g.title}</h3>
          <ul className="kf-gallery__cards">
            {g.examples.map((e) => {
              const thumb = thumbnailUrl(e.id);
              return (
                <li key={e.id}>
                  <button type="button" className="kf-gallery__card" onClick={() => onOpen(e)}>
                    {thumb ? (
                      <img src={thumb} alt="" width={96} height={96} />
                    ) : (
                      <span className="kf-gallery__nothumb" aria-hidden />
                    )}
                    <span className="kf-gallery__text">
                      <strong>{e.title}</strong>
                      <span>{oneLine(e.description)}</span>
                    </span>
                  </button>
                </li>
              );
            })}
          </ul>
        </section>
      ))}
    </dialog>
  );
}
