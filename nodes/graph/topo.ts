/**
 * Deterministic topological order (Kahn's algorithm, ready nodes taken in id order) and cycle
 * detection. The same graph always gives the same order, so the same shader source.
 */
export interface TopoResult {
  /** Nodes in dependency order, ties broken by id (code-unit order). Excludes nodes on or after a cycle. */
  readonly order: readonly string[];
  /** Each cycle found, as the node ids along it (first id repeated at the end). */
  readonly cycles: readonly (readonly string[])[];
  /** Nodes that could not be ordered: on a cycle or downstream of one. */
  readonly blocked: ReadonlySet<string>;
}

const byId = (a: string, b: string) => (a < b ? -1 : a > b ? 1 : 0);

export function topologicalOrder(
  ids: readonly string[],
  edges: readonly { from: string; to: string }[],
): TopoResult {
  const succ = new Map<string, string[]>();
  const indeg = new Map<string, number>();
  for (const id of ids) {
    succ.set(id, []);
    indeg.set(id, 0);
  }
  for (const e of edges) {
    if (!succ.has(e.from) || !succ.has(e.to)) continue;
    succ.get(e.from)!.push(e.to);
    indeg.set(e.to, indeg.get(e.to)! + 1);
  }
  // A sorted ready list; a binary-search insert keeps it sorted (graphs are at most a few thousand nodes).
  const ready = ids.filter((id) => indeg.get(id) === 0).sort(byId);
  const order: string[] = [];
  while (ready.length > 0) {
    const id = ready.shift()!;
    order.push(id);
    for (const next of succ.get(id)!) {
      const d = indeg.get(next)! - 1;
      indeg.set(next, d);
      if (d === 0) {
        let lo = 0;
        let hi = ready.length;
        while (lo < hi) {
          const mid = (lo + hi) >> 1;
          if (ready[mid] < next) lo = mid + 1;
          else hi = mid;
        }
        ready.splice(lo, 0, next);
      }
    }
  }
  const blocked = new Set(ids.filter((id) => indeg.get(id)! > 0));
  return { order, cycles: findCycles(blocked, succ), blocked };
}

/**
 * Whether adding `edge` to the graph (`ids`, `edges`) would close a cycle through it: the editor
 * refuses such a wire. Decided by the same ordering that evaluation uses, so the two agree: the
 * wire closes a cycle exactly when its source, orderable without it, is blocked with it (adding an
 * edge out of a node changes nothing upstream of it unless the edge leads back there). A source
 * that is already blocked (downstream of a cycle the graph has) cannot be told apart this way:
 * the wire is allowed, and analysis reports any cycle it closes like the first one.
 */
export function closesCycle(
  ids: readonly string[],
  edges: readonly { from: string; to: string }[],
  edge: { from: string; to: string },
): boolean {
  if (edge.from === edge.to) return true;
  if (topologicalOrder(ids, edges).blocked.has(edge.from)) return false;
  return topologicalOrder(ids, [...edges, edge]).blocked.has(edge.from);
}

/** One representative cycle per strongly connected knot among the blocked nodes (iterative DFS). */
function findCycles(blocked: ReadonlySet<string>, succ: ReadonlyMap<string, string[]>): string[][] {
  const cycles: string[][] = [];
  const state = new Map<string, 1 | 2>(); // 1 on stack, 2 done
  for (const start of [...blocked].sort(byId)) {
    if (state.has(start)) continue;
    const stack: { id: string; i: number }[] = [{ id: start, i: 0 }];
    const path: string[] = [start];
    state.set(start, 1);
    while (stack.length > 0) {
      const top = stack[stack.length - 1];
      const nexts = (succ.get(top.id) ?? []).filter((n) => blocked.has(n)).sort(byId);
      if (top.i < nexts.length) {
        const n = nexts[top.i++];
        const s = state.get(n);
        if (s === 1) cycles.push([...path.slice(path.indexOf(n)), n]);
        else if (s === undefined) {
          state.set(n, 1);
          stack.push({ id: n, i: 0 });
          path.push(n);
        }
      } else {
        state.set(top.id, 2);
        stack.pop();
        path.pop();
      }
    }
  }
  return cycles;
}
