/**
 * Fuzzy matching for the node palette: every query character must appear in order in the text;
 * matches at word starts and consecutive runs score higher, and the label counts most.
 */
import type { NodeDef } from '../../nodes/core/define-node.ts';
import type { PortType } from '../../nodes/core/ports.ts';
import { canConnect } from '../../nodes/core/ports.ts';

/** Score of `query` in `text` (higher is better), or null when not all characters match in order. */
export function fuzzyScore(query: string, text: string): number | null {
  const q = query.toLowerCase().replace(/\s+/g, '');
  if (q.length === 0) return 0;
  const t = text.toLowerCase();
  let score = 0;
  let ti = 0;
  let run = 0;
  for (const ch of q) {
    const found = t.indexOf(ch, ti);
    if (found < 0) return null;
    const wordStart = found === 0 || /[\s\-_(,]/.test(t[found - 1]);
    run = found === ti ? run + 1 : 0;
    score += 1 + (wordStart ? 3 : 0) + run * 2 - Math.min(3, (found - ti) * 0.1);
    ti = found + 1;
  }
  return score - t.length * 0.01;
}

/** What a wire dropped on the canvas is looking for: an input (or output) of this port type. */
export interface WireFilter {
  /** The dragged end is an output (`source`: we need an input) or an input (`target`). */
  readonly from: 'source' | 'target';
  readonly type: PortType;
}

/** The first port of `def` that fits the wire, or null. */
export function compatiblePort(def: NodeDef, filter: WireFilter): string | null {
  if (filter.from === 'source') {
    for (const [name, spec] of Object.entries(def.inputs))
      if (canConnect(filter.type, spec.type)) return name;
  } else {
    for (const [name, spec] of Object.entries(def.outputs))
      if (canConnect(spec.type, filter.type)) return name;
  }
  return null;
}

/** Node types matching `query` (best first; registry order on ties), limited to those fitting `filter`. */
export function searchNodeTypes(defs: readonly NodeDef[], query: string, filter?: WireFilter): NodeDef[] {
  const scored: { def: NodeDef; score: number; index: number }[] = [];
  defs.forEach((def, index) => {
    if (filter && compatiblePort(def, filter) === null) return;
    const fields: [string, number][] = [
      [def.label, 3],
      [def.type, 2],
      [def.category, 1],
      [def.doc, 0.5],
    ];
    let best: number | null = null;
    for (const [text, weight] of fields) {
      const s = fuzzyScore(query, text);
      if (s !== null && (best === null || s * weight > best)) best = s * weight;
    }
    if (best !== null) scored.push({ def, score: best, index });
  });
  return scored.sort((a, b) => b.score - a.score || a.index - b.index).map((s) => s.def);
}
