/** The keyboard shortcuts: one table for the handlers' documentation and the Help dialog. */
export interface Shortcut {
  readonly keys: readonly string[];
  readonly action: string;
}

export const SHORTCUTS: readonly { group: string; items: readonly Shortcut[] }[] = [
  {
    group: 'Graph',
    items: [
      { keys: ['Space', 'Ctrl K', 'Double-click'], action: 'Add a node (search palette)' },
      { keys: ['Drag a wire onto empty canvas'], action: 'Add a node that fits, wired in' },
      { keys: ['Shift drag'], action: 'Box-select' },
      { keys: ['Ctrl click'], action: 'Add to the selection' },
      { keys: ['Delete', 'Backspace'], action: 'Delete the selection' },
      { keys: ['Ctrl C', 'Ctrl X', 'Ctrl V'], action: 'Copy, cut, paste nodes (works across tabs)' },
      { keys: ['Ctrl D'], action: 'Duplicate the selection' },
      { keys: ['Ctrl A'], action: 'Select all nodes' },
      { keys: ['I'], action: 'Show or hide the inspector' },
      { keys: ['←', '→'], action: 'Resize the inspector (its edge focused; Shift: faster)' },
      { keys: ['Esc'], action: 'Close the inspector (focus in it)' },
      { keys: ['M'], action: 'Mute or unmute the selection (skipped; greyed)' },
      { keys: ['Ctrl G'], action: 'Group the selection into one node' },
      { keys: ['Ctrl Shift G'], action: 'Ungroup the selected groups' },
      { keys: ['Enter', 'Double-click a group'], action: 'Open the group (the breadcrumb leads back out)' },
      { keys: ['Double-click a wire'], action: 'Add a reroute point (double-click the dot to remove it)' },
    ],
  },
  {
    group: 'Keyboard only',
    items: [
      {
        keys: ['Tab', 'Shift Tab'],
        action: 'Go through the nodes, their ports and fields, and the render handles',
      },
      { keys: ['Enter'], action: 'Select the focused node (then ← ↑ → ↓ move it)' },
      {
        keys: ['Enter on a port'],
        action: 'Pick up a wire; Enter on a port of another node connects it (Esc drops it)',
      },
      {
        keys: ['← ↑ → ↓ on a render handle'],
        action: 'Move the point (Shift: 5× as far; each press is one undo step)',
      },
      {
        keys: ['↓ on a menu button', '↑ ↓ Home End in a menu'],
        action: 'Open the menu at its first item; move through its items (Esc: back to the button)',
      },
      {
        keys: ['Enter on Inspector'],
        action: 'Open the inspector and go into it; with no node selected it offers the render node',
      },
      {
        keys: ['Page Up / Page Down on a 3D handle'],
        action:
          'Move it away from / nearer to the camera by a tenth of its distance (arrows move it across the screen)',
      },
    ],
  },
  {
    group: 'Values',
    items: [
      { keys: ['Drag a field label'], action: 'Scrub a number (Shift: finer)' },
      { keys: ['↑', '↓'], action: 'Step a number field' },
      { keys: ['Enter', 'Esc'], action: 'Accept, cancel typing' },
    ],
  },
  {
    group: 'Render',
    items: [
      { keys: ['Drag'], action: 'Pan (or drag a handle of the construction)' },
      { keys: ['Wheel', 'Pinch'], action: 'Zoom about the cursor' },
      { keys: ['Shift drag handle'], action: 'Snap while dragging' },
      { keys: ['F'], action: 'Fit: show the whole picture' },
      {
        keys: ['Alt click', 'Inspect button'],
        action: 'Explain this pixel: its orbit, step by step (Esc closes)',
      },
    ],
  },
  {
    group: 'Document',
    items: [
      { keys: ['Ctrl Z'], action: 'Undo' },
      { keys: ['Ctrl Y', 'Ctrl Shift Z'], action: 'Redo' },
      { keys: ['Ctrl S'], action: 'Save as a .kleinflow.json file' },
      { keys: ['Ctrl O'], action: 'Open a file (.json or a Kleinflow PNG)' },
      { keys: ['Drop a file'], action: 'Open it (.json, Flower graph, Kleinflow PNG)' },
      { keys: ['Ctrl V'], action: 'Paste a whole graph or share link: opens it' },
      { keys: ['?'], action: 'This help' },
    ],
  },
  {
    group: 'Presentation',
    items: [
      {
        keys: ['Present button'],
        action: 'Present the construction from step 1 (Edit text: title, description, notes)',
      },
      { keys: ['→', 'PageDown'], action: 'Next step' },
      { keys: ['←', 'PageUp'], action: 'Previous step' },
      { keys: ['Home', 'End'], action: 'Back to the start, or the whole construction' },
      { keys: ['Esc'], action: 'Leave the presentation (first leaves a text field)' },
      { keys: ['?mode=present'], action: 'A present link: read-only, for the class (Copy present link)' },
    ],
  },
];
