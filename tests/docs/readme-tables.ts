/**
 * The README's generated tables — the node reference (from the registry), the keyboard
 * shortcuts (from src/app/shortcuts.ts) and the Help's quick starts (src/app/help/quick-start.ts) — so the documentation cannot drift from the code.
 * `UPDATE_README=1 npx vitest run tests/docs` rewrites them in place.
 */
import type { NodeDef } from '../../nodes/core/define-node.ts';
import { registry } from '../../nodes/types/index.ts';
import { QUICK_START, QUICK_START_3D, type QuickStep } from '../../src/app/help/quick-start.ts';
import { SHORTCUTS } from '../../src/app/shortcuts.ts';

const cell = (s: string) => s.replace(/\|/g, '\\|');
const ports = (ps: Readonly<Record<string, { type: string }>>) =>
  Object.entries(ps)
    .map(([name, p]) => `${name} (${p.type})`)
    .join(', ') || '—';

export function nodeReference(defs: readonly NodeDef[] = registry.all): string {
  const byCategory = new Map<string, NodeDef[]>();
  for (const d of defs) byCategory.set(d.category, [...(byCategory.get(d.category) ?? []), d]);
  const parts: string[] = [];
  for (const [category, list] of byCategory) {
    parts.push(`**${category}**\n`);
    parts.push('| type | what it does | inputs | outputs |');
    parts.push('|---|---|---|---|');
    for (const d of list)
      parts.push(`| \`${d.type}\` | ${cell(d.doc)} | ${cell(ports(d.inputs))} | ${cell(ports(d.outputs))} |`);
    parts.push('');
  }
  return parts.join('\n').trimEnd();
}

export function shortcutTable(): string {
  const rows = ['| keys | action |', '|---|---|'];
  for (const group of SHORTCUTS) {
    for (const s of group.items)
      rows.push(`| ${s.keys.map((k) => `<kbd>${cell(k)}</kbd>`).join(' / ')} | ${cell(s.action)} |`);
  }
  return rows.join('\n');
}

/** One of the Help dialog's quick starts (the 2D one by default), as a numbered list. */
export function quickStartList(steps: readonly QuickStep[] = QUICK_START): string {
  return steps.map((s, i) => `${i + 1}. **${s.title}.** ${s.detail}`).join('\n');
}

export const quickStart3dList = (): string => quickStartList(QUICK_START_3D);

/** Replaces the text between `<!-- NAME:begin -->` and `<!-- NAME:end -->`. */
export function replaceSection(text: string, name: string, body: string): string {
  const begin = `<!-- ${name}:begin -->`;
  const end = `<!-- ${name}:end -->`;
  const i = text.indexOf(begin);
  const j = text.indexOf(end);
  if (i < 0 || j < i) throw new Error(`README has no ${begin} … ${end} section`);
  return `${text.slice(0, i + begin.length)}\n${body}\n${text.slice(j)}`;
}
