import { readFileSync } from 'node:fs';
import { join } from 'node:path';
import { describe, expect, it } from 'vitest';
import type { GraphDoc } from '../../../../nodes/graph/document.ts';
import { evaluateGraph } from '../../../../nodes/graph/evaluate.ts';
import { registry } from '../../../../nodes/types/index.ts';
import { appMode } from '../../../../src/app/present/app-mode.ts';
import {
  constructionSteps,
  evaluationToDepth,
  evaluationUpTo,
  GROWTH_DEPTHS,
  renderReached,
} from '../../../../src/app/present/construction-steps.ts';
import { nextDepth } from '../../../../src/app/present/GrowthBar.tsx';

const root = join(import.meta.dirname, '..', '..', '..', '..');
const doc = JSON.parse(
  readFileSync(join(root, 'examples', 'kaleidoscope-333.kleinflow.json'), 'utf8'),
) as GraphDoc;
const evaluation = evaluateGraph(doc, registry);
const steps = constructionSteps(evaluation);

describe('construction steps', () => {
  it('follow the evaluation order, with the node label or else the type label', () => {
    expect(steps.map((s) => s.nodeId)).toEqual(evaluation.analysis.order);
    for (const s of steps) {
      const node = doc.nodes.find((n) => n.id === s.nodeId)!;
      expect(s.typeLabel).toBe(registry.get(node.type)!.label);
      expect(s.label).toBe(node.label ?? s.typeLabel);
    }
  });

  it('draw only what is built so far, growing step by step to the whole construction', () => {
    const sizes = steps.map((_, i) => evaluationUpTo(evaluation, steps, i).scene.overlays.length);
    expect(sizes[0]).toBe(0);
    for (let i = 1; i < sizes.length; i++) expect(sizes[i]).toBeGreaterThanOrEqual(sizes[i - 1]);
    expect(evaluationUpTo(evaluation, steps, steps.length)).toBe(evaluation);
    for (let i = 0; i <= steps.length; i++) {
      const built = new Set(steps.slice(0, i).map((s) => s.nodeId));
      const shown = evaluationUpTo(evaluation, steps, i).scene;
      expect(shown.overlays.every((o) => built.has(o.nodeId))).toBe(true);
      expect(shown.handles.every((h) => built.has(h.nodeId))).toBe(true);
      // A mirror appears at its own step (the overlay hatches it), never before.
      expect(shown.elements.every((e) => built.has(e.nodeId))).toBe(true);
      expect(shown.elements).toHaveLength(
        evaluation.scene.elements.filter((e) => built.has(e.nodeId)).length,
      );
    }
    expect(evaluationUpTo(evaluation, steps, 1).scene.elements).toHaveLength(0);
    // From the Render step on (when the picture shows) every mirror it uses is built.
    const render = steps.findIndex((s) => s.nodeId === evaluation.scene.renderNodeId);
    expect(evaluationUpTo(evaluation, steps, render + 1).scene.elements).toHaveLength(
      evaluation.scene.elements.length,
    );
  });

  it('reach the render node only at its own step', () => {
    const at = steps.findIndex((s) => s.nodeId === evaluation.scene.renderNodeId);
    expect(at).toBeGreaterThan(0);
    expect(renderReached(evaluation, steps, at)).toBe(false);
    expect(renderReached(evaluation, steps, at + 1)).toBe(true);
  });
});

describe('app mode', () => {
  it('reads ?mode=present / embed, anything else is the editor', () => {
    expect(appMode('?mode=present')).toBe('present');
    expect(appMode('?x=1&mode=embed')).toBe('embed');
    expect(appMode('?mode=<script>')).toBe('editor');
    expect(appMode('')).toBe('editor');
  });
});

describe('growth: the finished picture drawn with 1, 2, 5, 20 or all inversions', () => {
  it('caps the IIS budget of the plane and of space, never raises it, and leaves the rest alone', () => {
    expect(evaluationToDepth(evaluation, null)).toBe(evaluation);
    const one = evaluationToDepth(evaluation, 1);
    expect(one.scene.maxIterations).toBe(1);
    expect(one.scene.elements).toBe(evaluation.scene.elements);
    expect(evaluationToDepth(evaluation, 1e6).scene.maxIterations).toBe(evaluation.scene.maxIterations);
    const space = JSON.parse(
      readFileSync(join(root, 'examples', '3d', 'fig27-tiling-steps.kleinflow.json'), 'utf8'),
    ) as GraphDoc;
    const ev3 = evaluateGraph(space, registry);
    const five = evaluationToDepth(ev3, 5);
    expect(five.scene3d!.maxIterations).toBe(Math.min(5, ev3.scene3d!.maxIterations));
    expect(five.scene3d!.seeds).toBe(ev3.scene3d!.seeds);
  });

  it('G steps 1, 2, 5, 20, all and round again', () => {
    const seen: (number | null)[] = [];
    let d: number | null = null;
    for (let i = 0; i < GROWTH_DEPTHS.length + 2; i++) {
      d = nextDepth(d);
      seen.push(d);
    }
    expect(seen).toEqual([1, 2, 5, 20, null, 1]);
  });
});
