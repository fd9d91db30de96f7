/**
 * The system clipboard for nodes. Copy/cut/paste events carry the JSON synchronously and need no
 * permission (so another tab, or another browser window, can paste); the async Clipboard API is a
 * second path for when no event comes; an in-memory copy serves this tab when both are refused.
 */
import { type ClipboardData, parseClipboard, serializeClipboard } from '../state/clipboard.ts';

let memory: ClipboardData | null = null;

/** Remembers `data` and also tries the async Clipboard API (it may be refused without a prompt). */
export async function writeClipboard(data: ClipboardData): Promise<void> {
  memory = data;
  try {
    await navigator.clipboard?.writeText(serializeClipboard(data));
  } catch {
    // permission denied: the copy event or the in-memory copy still serve
  }
}

/** The nodes copied last in this tab. */
export const lastCopied = (): ClipboardData | null => memory;

/** Puts the nodes on a copy/cut event's clipboard. */
export function putOnEvent(e: ClipboardEvent, data: ClipboardData): boolean {
  if (!e.clipboardData) return false;
  memory = data;
  e.clipboardData.setData('text/plain', serializeClipboard(data));
  return true;
}

/**
 * The nodes a paste event carries; the in-memory copy when the event carries no text at all;
 * null when it carries something else (then the paste is not ours).
 */
export function readEvent(e: ClipboardEvent): ClipboardData | null {
  const text = e.clipboardData?.getData('text/plain') ?? '';
  return text ? parseClipboard(text) : memory;
}

/** The async Clipboard API's nodes when it holds some, else the in-memory copy. */
export async function readClipboard(): Promise<ClipboardData | null> {
  try {
    const read = navigator.clipboard?.readText();
    if (read) {
      const timeout = new Promise<null>((resolve) => setTimeout(() => resolve(null), 500));
      const text = await Promise.race([read, timeout]);
      const parsed = text ? parseClipboard(text) : null;
      if (parsed) return parsed;
    }
  } catch {
    // no permission: fall back to this tab's copy
  }
  return memory;
}
