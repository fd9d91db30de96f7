/**
 * The Formula node as a newcomer meets it: added from the palette on an empty canvas, a formula
 * typed on the node and committed with Enter (its result read out on the node), wired into a
 * second formula, a mistake shown on the node with the characters at fault, and undo bringing
 * the previous formula back into the field. Help lists the language.
 */
import { mkdirSync } from 'node:fs';
import { join } from 'node:path';
import type { Page } from 'playwright-core';
import { describe, expect, it } from 'vitest';
import { repoRoot, type ServedApp } from './app-server.ts';
import { servedAppForSuite } from './app-suite.ts';
import { addNode, connect, edgeCount, emptyCanvasPoint, nodeCount, nodeEl } from './editor-page.ts';

let app: ServedApp;
servedAppForSuite((served) => {
  app = served;
});

const readout = (page: Page, id: string) => nodeEl(page, id).locator('.kf-node__readout').textContent();
const formulaField = (page: Page, id: string) => nodeEl(page, id).getByLabel('formula', { exact: true });
/** A click on empty canvas: the field loses focus (Space then opens the palette again). */
async function clickCanvas(page: Page) {
  const at = await emptyCanvasPoint(page);
  await page.mouse.click(at.x, at.y);
}

describe('Formula node', () => {
  it('computes what is typed, feeds another node, names a mistake, and undoes', async () => {
    const context = await app.newContext({ width: 1280, height: 720 });
    const page = await context.newPage();
    await page.goto(app.url);
    await expect.poll(() => nodeCount(page), { timeout: 30_000 }).toBeGreaterThan(0);
    await page.getByRole('button', { name: 'New' }).click();
    await expect.poll(() => nodeCount(page)).toBe(0);

    const f = await addNode(page, 'formula', 120, 120);
    await expect.poll(() => readout(page, f)).toBe('3'); // a + b with a = 1, b = 2
    const field = formulaField(page, f);
    await field.click();
    await field.fill('sqrt(a*a + b*b) / 2');
    await field.press('Enter');
    await expect.poll(() => readout(page, f)).toBe('1.118');

    await clickCanvas(page);
    // A second formula reads the first through a wire.
    const g = await addNode(page, 'formula', 520, 160);
    await connect(page, f, 'value', g, 'a');
    await expect.poll(() => edgeCount(page)).toBe(1);
    await expect.poll(() => readout(page, g)).toBe('3.118'); // a + b, a = √5/2 wired, b = 2

    await field.click();
    await field.fill('a + sin(p)');
    await field.press('Enter');
    const badge = nodeEl(page, f).locator('[title*="KF327"]');
    await expect.poll(() => badge.count()).toBeGreaterThan(0);
    expect(await badge.first().getAttribute('title')).toContain(
      'characters 5–10 (“sin(p)”): sin takes sin(number)',
    );
    // The field itself says so: invalid for screen readers, the characters at fault underlined.
    expect(await formulaField(page, f).getAttribute('aria-invalid')).toBe('true');
    expect(await nodeEl(page, f).locator('.kf-field__problem mark').textContent()).toBe('sin(p)');
    mkdirSync(join(repoRoot, 'test-artifacts'), { recursive: true });
    await page.screenshot({ path: join(repoRoot, 'test-artifacts', 'formula-error.png') });

    // Undo: the field shows the formula before the mistake again, and the error is gone.
    await clickCanvas(page);
    await page.keyboard.press('Control+z');
    await expect.poll(() => formulaField(page, f).inputValue()).toBe('sqrt(a*a + b*b) / 2');
    await expect.poll(() => badge.count()).toBe(0);
    expect(await formulaField(page, f).getAttribute('aria-invalid')).toBeNull();

    await page.getByRole('button', { name: 'Help' }).click();
    const help = page.getByRole('dialog', { name: 'Help' });
    await expect.poll(() => help.getByRole('heading', { name: 'Formulas' }).count()).toBe(1);
    expect(await help.textContent()).toContain('rotate(point, number)');
    await context.close();
  }, 120_000);
});
