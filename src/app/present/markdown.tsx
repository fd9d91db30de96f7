/**
 * The presentation's small, safe Markdown subset, rendered as React elements (never as HTML, so a
 * title or note can hold `<script>` and it is shown as those characters):
 *   blank line → new paragraph, line break → <br>, lines starting "- " or "* " → a list,
 *   **bold**, *italic* or _italic_, `code`, [text](https://…) links (http and https only).
 * Anything else — HTML, images, headings — stays literal text.
 */
import { Fragment, type ReactNode } from 'react';

/** One inline token: the first of these that matches at a position wins. */
const INLINE =
  /\*\*([^*\n]+)\*\*|`([^`\n]+)`|\*([^*\n]+)\*|_([^_\n]+)_|\[([^\]\n]+)\]\((https?:\/\/[^\s)]+)\)/g;

export function renderInline(text: string): ReactNode[] {
  const out: ReactNode[] = [];
  let last = 0;
  for (const m of text.matchAll(INLINE)) {
    const at = m.index;
    if (at > last) out.push(text.slice(last, at));
    const key = out.length;
    if (m[1] !== undefined) out.push(<strong key={key}>{m[1]}</strong>);
    else if (m[2] !== undefined) out.push(<code key={key}>{m[2]}</code>);
    else if (m[3] !== undefined || m[4] !== undefined) out.push(<em key={key}>{m[3] ?? m[4]}</em>);
    else
      out.push(
        <a key={key} href={m[6]} target="_blank" rel="noopener noreferrer">
          {m[5]}
        </a>,
      );
    last = at + m[0].length;
  }
  if (last < text.length) out.push(text.slice(last));
  return out;
}

const LIST_ITEM = /^\s*[-*]\s+/;

/** Paragraphs and lists of `text` (see the module comment for the subset). */
export function Markdown({ text, className }: { text: string; className?: string }) {
  const blocks = text
    .replace(/\r\n?/g, '\n')
    .split(/\n\s*\n/)
    .map((b) => b.trim())
    .filter((b) => b.length > 0);
  return (
    <div className={className}>
      {blocks.map((block, i) => {
        const lines = block.split('\n');
        if (lines.every((l) => LIST_ITEM.test(l)))
          return (
            // biome-ignore lint/suspicious/noArrayIndexKey: blocks have no identity but their order
            <ul key={i}>
              {lines.map((l, j) => (
                // biome-ignore lint/suspicious/noArrayIndexKey: as above
                <li key={j}>{renderInline(l.replace(LIST_ITEM, ''))}</li>
              ))}
            </ul>
          );
        return (
          // biome-ignore lint/suspicious/noArrayIndexKey: as above
          <p key={i}>
            {lines.map((l, j) => (
              // biome-ignore lint/suspicious/noArrayIndexKey: as above
              <Fragment key={j}>
                {j > 0 && <br />}
                {renderInline(l)}
              </Fragment>
            ))}
          </p>
        );
      })}
    </div>
  );
}
