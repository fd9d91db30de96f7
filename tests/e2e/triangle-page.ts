/**
 * The classroom mirror triangle built as a teacher builds it, from the palette: points A, B, C,
 * lines AB, AC, BC (the order one writes them in, so the AC mirror keeps the outside), a Line
 * reflection on each, all wired into one Render. Shared by the mirror suites.
 */
import type { Page } from 'playwright-core';
import { expect } from 'vitest';
import { addNode, connect, edgeCount, nodeCount, setField } from './editor-page.ts';

export interface BuiltTriangle {
  readonly points: string[];
  readonly mirrors: string[];
  readonly render: string;
}

/** Starts a new document and builds the triangle with corners `corners` (x, y as typed). */
export async function buildTriangle(
  page: Page,
  corners: readonly (readonly [string, string])[],
): Promise<BuiltTriangle> {
  await expect.poll(() => nodeCount(page)).toBeGreaterThan(0);
  await page.getByRole('button', { name: 'New' }).click();
  await expect.poll(() => nodeCount(page)).toBe(0);
  const rows = [30, 220, 410];
  const points: string[] = [];
  const mirrors: string[] = [];
  for (const [i, y] of rows.entries()) {
    const p = await addNode(page, 'point', 30, y);
    await setField(page, p, 'x', corners[i][0]);
    await setField(page, p, 'y', corners[i][1]);
    points.push(p);
  }
  const render = await addNode(page, 'render', 900, 160);
  const pairs = [
    [0, 1],
    [0, 2],
    [1, 2],
  ];
  for (const [i, [from, to]] of pairs.entries()) {
    const line = await addNode(page, 'line', 320, rows[i]);
    const mirror = await addNode(page, 'line reflection', 610, rows[i]);
    await connect(page, points[from], 'point', line, 'a');
    await connect(page, points[to], 'point', line, 'b');
    await connect(page, line, 'line', mirror, 'line');
    await connect(page, mirror, 'element', render, 'elements');
    mirrors.push(mirror);
  }
  await expect.poll(() => edgeCount(page)).toBe(12);
  return { points, mirrors, render };
}
