/** "Copy present link" and the iframe snippet for a class page; both carry the graph in the URL. */
import { useMemo, useState } from 'react';
import { useEditorState } from '../../state/use-store.ts';
import { copyText } from '../io/use-document-io.tsx';
import { presentLinks } from './present-link.ts';

export function ShareBox() {
  const doc = useEditorState((s) => s.doc);
  const [said, setSaid] = useState('');
  const links = useMemo(() => presentLinks(doc, window.location), [doc]);
  if (!links.ok) return <p className="kf-present-edit__hint">No link: {links.message}</p>;
  const copy = async (text: string, what: string) =>
    setSaid((await copyText(text)) ? `${what} copied.` : `The browser refused to copy the ${what}.`);
  return (
    <section className="kf-present-share" aria-label="Share the presentation">
      <h3 className="kf-present-edit__heading">For the class</h3>
      <button
        type="button"
        className="kf-button"
        title="A read-only presentation that opens at step 1"
        onClick={() => void copy(links.present, 'Present link')}
      >
        Copy present link
      </button>
      <label className="kf-present-edit__label">
        <span>Embed in a class page</span>
        <textarea
          className="kf-present-edit__field kf-present-share__snippet"
          aria-label="Embed snippet"
          readOnly
          rows={3}
          value={links.embed}
          onFocus={(e) => e.currentTarget.select()}
        />
      </label>
      <button type="button" className="kf-button" onClick={() => void copy(links.embed, 'Embed snippet')}>
        Copy embed snippet
      </button>
      <p className="kf-present-edit__hint" role="status">
        {said}
      </p>
    </section>
  );
}
