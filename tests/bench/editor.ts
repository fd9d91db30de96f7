/**
 * The editor at scale in real Chromium: opens a generated 500-node graph (98 IIS elements) from
 * the autosave and drags nodes with 30 real mouse moves, recording animation-frame timestamps in
 * the page. Prints the open time and the frame intervals during the drags (median, 95th
 * percentile, worst) and the time from releasing a node to the next frame after the drop. Like
 * every bench it reports and never fails on a time; the machine runs SwiftShader on the CPU.
 */
import { serveApp } from '../e2e/app-server.ts';
import { draggableNode, dragNode, editorScaleGraph, openLarge, quantile } from '../e2e/scale-page.ts';

const NODES = 500;
const DRAGS = 5;

export async function run(): Promise<void> {
  console.log(`\nEditor: ${NODES}-node graph in Chromium, ${DRAGS} drags of 30 mouse moves each`);
  const app = await serveApp();
  try {
    const context = await app.newContext({ width: 1280, height: 720 });
    const { page, openMs } = await openLarge(context, app.url, editorScaleGraph(NODES), 120_000);
    console.log(`  open (navigation → all nodes on screen): ${openMs} ms`);
    const frames: number[] = [];
    const drops: number[] = [];
    for (let i = 0; i < DRAGS; i++) {
      await page.waitForTimeout(500);
      const id = await draggableNode(page);
      const r = await dragNode(page, id, i % 2 === 0 ? 160 : -160, i % 2 === 0 ? 90 : -90);
      frames.push(...r.frameMs);
      drops.push(r.dropMs);
    }
    const f = (q: number) => quantile(frames, q).toFixed(1).padStart(7);
    console.log(
      `  frame interval during drags, ms (${frames.length} frames): median ${f(0.5)}  p95 ${f(0.95)}  max ${f(1)}`,
    );
    console.log(
      `  drop (release → next frame), ms: median ${quantile(drops, 0.5).toFixed(1)}  max ${quantile(drops, 1).toFixed(1)}`,
    );
  } finally {
    await app.close();
  }
}
