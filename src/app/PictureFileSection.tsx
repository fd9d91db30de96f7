/**
 * The image node's "Choose picture…" in the inspector: the file becomes the node's picture (src,
 * width, height) in one undo step, shrunk to fit the limits when it must (picture-file.ts). With a
 * live source the picture is the fallback, so the control is there for every source.
 */
import { useState } from 'react';
import type { GraphNode } from '../../nodes/graph/document.ts';
import { useStore } from '../state/use-store.ts';
import { FileChoice } from './FileChoice.tsx';
import { pictureFromFile } from './picture-file.ts';

export function PictureFileSection({ node }: { node: GraphNode }) {
  const store = useStore();
  const [note, setNote] = useState<{ error: boolean; text: string } | null>(null);
  if (node.type !== 'image') return null;
  const src = String(node.params.src ?? '');

  const choose = async (file: File | undefined) => {
    if (!file) return;
    setNote({ error: false, text: `Reading “${file.name}”…` });
    try {
      const picture = await pictureFromFile(file);
      store.dispatch(
        { type: 'set-params', patches: [{ nodeId: node.id, params: { ...picture } }] },
        'choose picture',
      );
      setNote({ error: false, text: `“${file.name}”: ${picture.width} × ${picture.height} pixels` });
    } catch (e) {
      setNote({ error: true, text: e instanceof Error ? e.message : String(e) });
    }
  };
  const clear = () => {
    store.dispatch(
      { type: 'set-params', patches: [{ nodeId: node.id, params: { src: '', width: 0, height: 0 } }] },
      'built-in picture',
    );
    setNote(null);
  };

  return (
    <>
      <h3>Picture</h3>
      <FileChoice label="Choose picture" accept="image/*" onFile={(f) => void choose(f)} />
      {src !== '' && (
        <button type="button" className="kf-button" onClick={clear}>
          Use the built-in picture
        </button>
      )}
      <p
        className={note?.error ? 'kf-inspector__hint kf-inspector__hint--error' : 'kf-inspector__hint'}
        role="status"
        data-testid="picture-status"
      >
        {note?.text ??
          (src === ''
            ? 'The built-in checker with an arrow (shows which way is up).'
            : 'A picture kept in the document.')}
      </p>
    </>
  );
}
