import { describe, expect, it } from 'vitest';
import { emptyDocument, type GraphDoc } from '../../../nodes/graph/document.ts';
import { registry } from '../../../nodes/types/index.ts';
import { HISTORY_LIMIT } from '../../../src/state/history.ts';
import { createEditorStore } from '../../../src/state/store.ts';

const doc = (): GraphDoc => ({
  ...emptyDocument('t'),
  nodes: [{ id: 'p', type: 'point', position: [0, 0], params: { x: 0, y: 0 } }],
});
const x = (d: GraphDoc) => d.nodes[0]?.params.x;
const setX = (v: number) => ({ type: 'set-params' as const, patches: [{ nodeId: 'p', params: { x: v } }] });

describe('editor store: history', () => {
  it('undo and redo walk the steps back and forth', () => {
    const s = createEditorStore(doc(), registry);
    s.dispatch(setX(1));
    s.dispatch(setX(2));
    s.undo();
    expect(x(s.getState().doc)).toBe(1);
    s.undo();
    expect(x(s.getState().doc)).toBe(0);
    s.undo(); // nothing left: no change
    expect(x(s.getState().doc)).toBe(0);
    s.redo();
    s.redo();
    expect(x(s.getState().doc)).toBe(2);
  });

  it('a new edit after undo drops the redo branch', () => {
    const s = createEditorStore(doc(), registry);
    s.dispatch(setX(1));
    s.undo();
    s.dispatch(setX(5));
    s.redo();
    expect(x(s.getState().doc)).toBe(5);
    expect(s.getState().history.future).toHaveLength(0);
  });

  it('a gesture (many previews, one commit) is ONE undo step back to where it began', () => {
    const s = createEditorStore(doc(), registry);
    for (let i = 1; i <= 30; i++) s.preview(setX(i / 10));
    expect(x(s.getState().doc)).toBe(3);
    expect(s.getState().history.past).toHaveLength(0);
    s.commit(setX(3.5));
    expect(s.getState().history.past).toHaveLength(1);
    s.undo();
    expect(x(s.getState().doc)).toBe(0);
    s.redo();
    expect(x(s.getState().doc)).toBe(3.5);
  });

  it('cancelling a gesture restores the document it began with', () => {
    const s = createEditorStore(doc(), registry);
    s.preview(setX(9));
    s.cancelGesture();
    expect(x(s.getState().doc)).toBe(0);
    expect(s.getState().history.past).toHaveLength(0);
  });

  it('silent view changes are not steps, and undo keeps the current view', () => {
    const s = createEditorStore(doc(), registry);
    s.dispatch(setX(1));
    s.dispatchSilently({ type: 'set-view', view: { center: [3, 3], scale: 9 } });
    expect(s.getState().history.past).toHaveLength(1);
    s.undo();
    expect(x(s.getState().doc)).toBe(0);
    expect(s.getState().doc.view).toEqual({ center: [3, 3], scale: 9 });
  });

  it('the 3D camera is view state too: silent, and undo keeps the current camera', () => {
    const s = createEditorStore(doc(), registry);
    const camera: NonNullable<GraphDoc['camera3d']> = { position: [4, 4, 4], target: [0, 0, 1], fovDeg: 35 };
    s.dispatch(setX(1));
    s.dispatchSilently({ type: 'set-camera-3d', camera });
    expect(s.getState().history.past).toHaveLength(1);
    s.undo();
    expect(x(s.getState().doc)).toBe(0);
    expect(s.getState().doc.camera3d).toEqual(camera);
    s.redo();
    expect(s.getState().doc.camera3d).toEqual(camera);
  });

  it('selection is not history: selecting never adds a step, and deleted nodes leave the selection', () => {
    const s = createEditorStore(doc(), registry);
    s.setSelection(['p']);
    expect(s.getState().history.past).toHaveLength(0);
    s.dispatch({ type: 'remove', nodeIds: ['p'] });
    expect(s.getState().selection.size).toBe(0);
    s.undo();
    expect(s.getState().doc.nodes).toHaveLength(1);
  });

  it('keeps at most HISTORY_LIMIT steps', () => {
    const s = createEditorStore(doc(), registry);
    for (let i = 1; i <= HISTORY_LIMIT + 20; i++) s.dispatch(setX(i));
    expect(s.getState().history.past).toHaveLength(HISTORY_LIMIT);
    for (let i = 0; i < HISTORY_LIMIT + 5; i++) s.undo();
    expect(x(s.getState().doc)).toBe(20);
  });

  it('notifies subscribers on every state change', () => {
    const s = createEditorStore(doc(), registry);
    let calls = 0;
    const off = s.subscribe(() => calls++);
    s.dispatch(setX(1));
    s.setSelection(['p']);
    off();
    s.dispatch(setX(2));
    expect(calls).toBe(2);
  });
});
