/**
 * A GLSL function with the functions it calls. The assembler emits every function the shader uses
 * once, dependencies first, in a deterministic order (first use, depth first), so the same scene
 * always gives the same source.
 */
export interface GlslFunction {
  /** The function's name, as called from generated code. */
  readonly name: string;
  /** Its full definition (one or more lines, no trailing newline). */
  readonly code: string;
  readonly deps?: readonly GlslFunction[];
}

export function glslFunction(name: string, code: string, deps: readonly GlslFunction[] = []): GlslFunction {
  return { name, code: code.trim(), deps };
}

/** The definitions of `roots` and everything they call, each once, callees before callers. */
export function collectFunctions(roots: readonly GlslFunction[]): string[] {
  const seen = new Set<string>();
  const out: string[] = [];
  const visit = (f: GlslFunction) => {
    if (seen.has(f.name)) return;
    seen.add(f.name);
    for (const d of f.deps ?? []) visit(d);
    out.push(f.code);
  };
  for (const f of roots) visit(f);
  return out;
}
