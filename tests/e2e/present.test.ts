/**
 * Presenting, as a teacher does it: Present from the top bar opens at step 1 with the step list,
 * the author writes the title, description and step notes (Markdown shown as text styling, never
 * HTML), they are saved in the document and come back from the file; the present link and the
 * embed snippet open a read-only presentation (another link typed into its address bar shows that
 * graph, still read-only); Esc goes back to the editor.
 */
import { mkdirSync, readFileSync } from 'node:fs';
import { join } from 'node:path';
import type { Page } from 'playwright-core';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import type { GraphDoc } from '../../nodes/graph/document.ts';
import { shareLinkFor } from '../../src/app/io/share-link.ts';
import { repoRoot, type ServedApp, serveApp } from './app-server.ts';
import { currentDoc, openViaPicker } from './io-page.ts';

const shots = join(repoRoot, 'test-artifacts');
const example = (name: string) => readFileSync(join(repoRoot, 'examples', `${name}.kleinflow.json`), 'utf8');
const LAST_NOTE = 'The **Render** node reflects the triangle in its three mirrors until the plane is full.';
const THIRD = 'Third: <img src=x onerror="window.__pwned=1"> stays text.';

describe('presentation', () => {
  let app: ServedApp;
  let page: Page;
  const problems: string[] = [];
  const watch = (p: Page) => {
    p.on('console', (m) => m.type() === 'error' && problems.push(`console: ${m.text()}`));
    p.on('pageerror', (e) => problems.push(`pageerror: ${e.message}`));
    return p;
  };
  beforeAll(async () => {
    mkdirSync(shots, { recursive: true });
    app = await serveApp();
    page = watch(await (await app.newContext({ width: 1280, height: 800 })).newPage());
    await page.goto(app.url);
    await openViaPicker(page, 'k333.kleinflow.json', Buffer.from(example('kaleidoscope-333')));
    await page.locator('.react-flow__node').first().waitFor();
  });
  afterAll(() => app?.close());

  const stepNow = () => page.getByTestId('step-now');

  it('Present opens at step 1 with every step listed; the graph is gone and nothing can be dragged', async () => {
    await expect.poll(() => page.locator('[data-handle]').count()).toBeGreaterThan(0); // the editor's handles
    await page.getByRole('button', { name: 'Present' }).click();
    await page.getByTestId('present-mode').waitFor();
    expect(await page.locator('.react-flow').count()).toBe(0);
    const total = Number(((await stepNow().textContent()) ?? '').match(/Step 1 \/ (\d+)/)![1]);
    expect(total).toBeGreaterThan(3);
    const list = page.getByRole('navigation', { name: 'Step list' });
    expect(await list.getByRole('button').count()).toBe(total);
    expect(await list.locator('[aria-current="step"]').textContent()).toMatch(/^1/);
    expect(await page.locator('[data-handle]').count()).toBe(0);
    await list.getByRole('button').nth(2).click();
    expect(await stepNow().textContent()).toContain(`Step 3 / ${total}`);
    await page.keyboard.press('ArrowLeft');
    expect(await stepNow().textContent()).toContain(`Step 2 / ${total}`);
  });

  it('once the picture is shown it grows with 1, 2, 5, 20 or all inversions (buttons and G)', async () => {
    const growth = page.getByRole('group', { name: /Inversions drawn/ });
    expect(await growth.count()).toBe(0); // step 2: no picture yet, nothing to grow
    await page.keyboard.press('End');
    await growth.waitFor();
    const picture = page.getByTestId('present-mode').locator('canvas').first();
    const all = growth.getByRole('button', { name: 'all' });
    expect(await all.getAttribute('aria-pressed')).toBe('true');
    // Wait for the whole picture to settle (two equal shots), then draw it with one inversion.
    let whole = await picture.screenshot();
    await expect
      .poll(
        async () => {
          const next = await picture.screenshot();
          const same = next.equals(whole);
          whole = next;
          return same;
        },
        { timeout: 60_000 },
      )
      .toBe(true);
    await growth.getByRole('button', { name: '1', exact: true }).click();
    await expect
      .poll(async () => (await picture.screenshot()).equals(whole), { timeout: 60_000 })
      .toBe(false);
    await page.keyboard.press('g'); // 1 → 2
    expect(await growth.getByRole('button', { name: '2', exact: true }).getAttribute('aria-pressed')).toBe(
      'true',
    );
    await all.click();
    expect(await all.getAttribute('aria-pressed')).toBe('true');
    // back to step 2 for the next test
    await page.keyboard.press('Home');
    await page.keyboard.press('ArrowRight');
    await page.keyboard.press('ArrowRight');
    expect(await stepNow().textContent()).toMatch(/Step 2 \//);
  });

  it('the author writes title, description and step notes; Markdown styles them, HTML stays text', async () => {
    await page.getByRole('button', { name: 'Edit text' }).click();
    const panel = page.getByRole('complementary', { name: 'Presentation text' });
    await panel.getByRole('textbox', { name: 'Title' }).fill('Three mirrors');
    await panel
      .getByRole('textbox', { name: 'Description' })
      .fill('A **kaleidoscope** from one triangle.\n\n- three mirrors\n- corners of *60°*');
    await panel.getByRole('textbox', { name: /^Note for step 2/ }).fill('Now the **second** corner.');
    await page.getByRole('heading', { name: 'Presentation text' }).click(); // leaving the field commits it
    expect(await page.getByRole('heading', { level: 1 }).textContent()).toBe('Three mirrors');
    const head = page.locator('.kf-present__head');
    expect(await head.locator('strong').textContent()).toBe('kaleidoscope');
    expect(await head.locator('li').count()).toBe(2);
    const note = page.getByRole('region', { name: 'Step note' });
    expect(await note.locator('strong').textContent()).toBe('second');
    await page.keyboard.press('ArrowRight');
    await note.waitFor({ state: 'detached' });
    await panel.getByRole('textbox', { name: /^Note for step 3/ }).fill(THIRD);
    await page.keyboard.press('ArrowLeft'); // typing: the arrow moves the caret, not the step
    expect(await stepNow().textContent()).toMatch(/Step 3 \//);
    await page.keyboard.press('Escape'); // the first Esc leaves the field (and commits it) …
    expect(await page.getByTestId('present-mode').count()).toBe(1);
    expect(await note.textContent()).toBe(THIRD);
    expect(await page.locator('img[src="x"]').count()).toBe(0);
    expect(await page.evaluate(() => (window as { __pwned?: number }).__pwned)).toBeUndefined();
    await page.setViewportSize({ width: 390, height: 844 });
    await page.keyboard.press('ArrowLeft');
    await note.waitFor();
    await page.waitForTimeout(400);
    await page.screenshot({ path: join(shots, 'present-edit-phone.png') });
    await page.setViewportSize({ width: 1280, height: 800 });
    await page.keyboard.press('End');
    await panel.getByRole('textbox', { name: /^Note for step \d+: Render/ }).fill(LAST_NOTE);
    await page.getByRole('heading', { name: 'Presentation text' }).click();
    await note.waitFor();
    await page.waitForTimeout(1500); // the picture fades in and refines
    await page.screenshot({ path: join(shots, 'present-edit.png') });
  });

  it('gives a present link and an iframe snippet that open the read-only presentation at step 1', async () => {
    await page.getByRole('button', { name: 'Copy present link' }).click();
    await page.getByText('Present link copied.').waitFor();
    const link = await page.evaluate(() => navigator.clipboard.readText());
    expect(link).toMatch(/\?mode=present#g=/);
    const snippet = await page.getByRole('textbox', { name: 'Embed snippet' }).inputValue();
    expect(snippet).toMatch(/^<iframe src="[^"]+\?mode=present#g=[^"]+" title="Three mirrors"/);
    const student = watch(await (await app.newContext({ width: 1000, height: 700 })).newPage());
    await student.goto(link);
    await student.getByTestId('present-mode').waitFor();
    await student.getByRole('heading', { name: 'Three mirrors' }).waitFor();
    expect(await student.getByTestId('step-now').textContent()).toMatch(/^Step 1 \//);
    expect(await student.getByRole('button', { name: 'Edit text' }).count()).toBe(0);
    await student.keyboard.press('ArrowRight');
    expect(await student.getByRole('region', { name: 'Step note' }).textContent()).toBe(
      'Now the second corner.',
    );
    expect(await student.locator('[data-handle]').count()).toBe(0);
    await student.keyboard.press('Escape'); // nothing to leave for the audience
    expect(await student.getByTestId('present-mode').count()).toBe(1);
    expect(await student.getByRole('link', { name: 'Edit in Kleinflow' }).getAttribute('href')).toMatch(
      /#g=/,
    );
    // Another present link typed into the address bar (a hash change) shows that graph, read-only.
    const next = JSON.parse(example('kaleidoscope-333')) as GraphDoc;
    next.meta.title = 'Next lesson';
    const typed = shareLinkFor(next, { origin: new URL(app.url).origin, pathname: '/' });
    if (!typed.ok) throw new Error(typed.message);
    await student.evaluate((hash) => {
      window.location.hash = hash;
    }, new URL(typed.url).hash);
    await student.getByRole('heading', { name: 'Next lesson' }).waitFor();
    expect(await student.getByRole('button', { name: 'Edit text' }).count()).toBe(0);
    expect(await student.locator('[data-handle]').count()).toBe(0);
    await student.close();
  });

  it('Esc leaves the presentation; the text is in the saved document and comes back from the file', async () => {
    await page.keyboard.press('?'); // the editor's Help key does nothing while presenting …
    await page.keyboard.press('Escape');
    await page.locator('.react-flow').waitFor();
    expect(await page.getByRole('dialog', { name: 'Help' }).count()).toBe(0); // … nor after
    const doc = (await currentDoc(page)) as {
      meta: { title: string; description: string; stepNotes: Record<string, string> };
    };
    expect(doc.meta.title).toBe('Three mirrors');
    expect(doc.meta.description).toContain('**kaleidoscope**');
    expect(Object.values(doc.meta.stepNotes).sort()).toEqual([
      'Now the **second** corner.',
      LAST_NOTE,
      THIRD,
    ]);
    await openViaPicker(page, 'k333.kleinflow.json', Buffer.from(example('kaleidoscope-333')));
    await page.getByRole('button', { name: 'Present' }).click();
    expect(await page.getByRole('navigation', { name: 'Step list' }).getByText('✎').count()).toBe(0);
    await page.keyboard.press('Escape');
    await openViaPicker(page, 'mine.kleinflow.json', Buffer.from(JSON.stringify(doc)));
    await page.getByRole('textbox', { name: 'Document title' }).waitFor();
    await expect
      .poll(() => page.getByRole('textbox', { name: 'Document title' }).inputValue())
      .toBe('Three mirrors');
    await page.getByRole('button', { name: 'Present' }).click();
    expect(await page.getByRole('navigation', { name: 'Step list' }).getByText('✎').count()).toBe(3);
    await page.keyboard.press('Escape');
  });

  it('no console errors', () => {
    expect(problems).toEqual([]);
  });
});
