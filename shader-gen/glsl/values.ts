/**
 * Where scene values go in the generated shader: uniforms (the default: values change without a
 * recompile) or literals (baked). Every call returns the GLSL expression to use in the code and,
 * for uniforms, records the declaration and the value to upload.
 */
import { floatLiteral, gpuFloat, intLiteral, vecLiteral } from './literal.ts';

export type UniformType = 'float' | 'int' | 'vec2' | 'vec3' | 'vec4' | 'vec4[]' | 'float[]';

/** One uniform to upload: arrays are flattened (`vec4[]` holds 4 numbers per element). */
export interface UniformEntry {
  name: string;
  type: UniformType;
  value: number[];
}

/** The packed element data lives in one array: `uniform vec4 u_el[N]`. */
export const ELEMENT_ARRAY = 'u_el';
/** Picture samplers are `u_image0`, `u_image1`, …; sampler N reads texture unit N. */
export const PICTURE_SAMPLER = 'u_image';

const VEC_TYPES = { 2: 'vec2', 3: 'vec3', 4: 'vec4' } as const;

export class SceneValues {
  private readonly uniforms = new Map<string, UniformEntry>();
  private readonly rows: number[] = [];
  private readonly pictureSrcs: string[] = [];

  constructor(readonly baked: boolean) {}

  float(name: string, x: number): string {
    if (this.baked) return floatLiteral(x);
    return this.declare({ name, type: 'float', value: [x] });
  }

  int(name: string, n: number): string {
    if (this.baked) return intLiteral(n);
    return this.declare({ name, type: 'int', value: [n] });
  }

  vec(name: string, values: readonly number[]): string {
    if (this.baked) return vecLiteral(values);
    const type = VEC_TYPES[values.length as 2 | 3 | 4];
    if (!type) throw new Error(`no GLSL vector of ${values.length} components`);
    return this.declare({ name, type, value: [...values] });
  }

  /**
   * Appends one element's packed data (a multiple of 4 numbers) to the element array and returns
   * an expression per vec4: `u_el[i]`, or a `vec4(…)` literal when baked.
   */
  elementRows(data: readonly number[]): string[] {
    if (data.length % 4 !== 0) throw new Error(`element data of ${data.length} numbers is not whole vec4s`);
    const exprs: string[] = [];
    for (let i = 0; i < data.length; i += 4) {
      const row = data.slice(i, i + 4);
      exprs.push(this.baked ? vecLiteral(row) : `${ELEMENT_ARRAY}[${this.rows.length / 4}]`);
      if (!this.baked) this.rows.push(...row.map(gpuFloat));
    }
    return exprs;
  }

  /**
   * The sampler of picture `src`: `u_image0`, `u_image1`, … in order of first use, one per
   * distinct src. Samplers stay uniforms when baked (a texture cannot be a literal).
   */
  picture(src: string): string {
    let i = this.pictureSrcs.indexOf(src);
    if (i < 0) {
      i = this.pictureSrcs.length;
      this.pictureSrcs.push(src);
    }
    return `${PICTURE_SAMPLER}${i}`;
  }

  /** The pictures' srcs by sampler number (texture unit i holds pictures()[i]). */
  pictures(): string[] {
    return [...this.pictureSrcs];
  }

  /** Every scene uniform, sorted by name (the element array included when it is not empty). */
  entries(): UniformEntry[] {
    const all = [...this.uniforms.values()];
    if (this.rows.length > 0) all.push({ name: ELEMENT_ARRAY, type: 'vec4[]', value: [...this.rows] });
    return all.sort((a, b) => (a.name < b.name ? -1 : a.name > b.name ? 1 : 0));
  }

  private declare(entry: UniformEntry): string {
    if (this.uniforms.has(entry.name)) throw new Error(`uniform ${entry.name} declared twice`);
    this.uniforms.set(
      entry.name,
      entry.type === 'int' ? entry : { ...entry, value: entry.value.map(gpuFloat) },
    );
    return entry.name;
  }
}

/** The GLSL declaration of a uniform entry. */
export function declaration(u: UniformEntry): string {
  if (u.type === 'vec4[]') return `uniform vec4 ${u.name}[${u.value.length / 4}];`;
  if (u.type === 'float[]') return `uniform float ${u.name}[${u.value.length}];`;
  return `uniform ${u.type} ${u.name};`;
}

/**
 * Uniform vectors (vec4 rows) a uniform occupies, counted the conservative way (GLSL ES 3.00
 * §A.7 may pack small uniforms together; we never rely on it): one row per scalar or vector,
 * one per array element.
 */
export function uniformRows(u: Pick<UniformEntry, 'type' | 'value'>): number {
  if (u.type === 'vec4[]') return u.value.length / 4;
  if (u.type === 'float[]') return u.value.length;
  return 1;
}
