/**
 * System clipboard access for nodes: writes through navigator.clipboard (so another tab can paste)
 * and keeps an in-memory copy for when the browser refuses (no permission, insecure context).
 */
import { type ClipboardData, parseClipboard, serializeClipboard } from '../state/clipboard.ts';

let memory: ClipboardData | null = null;

export async function writeClipboard(data: ClipboardData): Promise<void> {
  memory = data;
  try {
    await navigator.clipboard?.writeText(serializeClipboard(data));
  } catch {
    // permission denied: the in-memory copy still serves this tab
  }
}

/** The system clipboard's nodes when it holds some, else the in-memory copy. */
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
