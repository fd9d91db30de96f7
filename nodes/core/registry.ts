/** A lookup of node types built from one list (nodes/types/index.ts holds the app's list). */
import type { NodeDef } from './define-node.ts';

export interface NodeRegistry {
  get(type: string): NodeDef | undefined;
  readonly all: readonly NodeDef[];
}

export function createRegistry(defs: readonly NodeDef[]): NodeRegistry {
  const byType = new Map<string, NodeDef>();
  for (const def of defs) {
    if (byType.has(def.type)) throw new Error(`node type "${def.type}" is registered twice`);
    byType.set(def.type, def);
  }
  return { get: (type) => byType.get(type), all: defs };
}
