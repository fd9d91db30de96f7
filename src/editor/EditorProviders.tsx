/** The contexts every node component reads: the edit actions and the keyboard wire in progress. */
import type { ReactNode } from 'react';
import { type EditorActions, EditorContext } from './editor-context.ts';
import { type KeyboardWire, KeyboardWireContext } from './keyboard-wire.ts';

export function EditorProviders(props: { actions: EditorActions; wire: KeyboardWire; children: ReactNode }) {
  return (
    <EditorContext.Provider value={props.actions}>
      <KeyboardWireContext.Provider value={props.wire}>{props.children}</KeyboardWireContext.Provider>
    </EditorContext.Provider>
  );
}
