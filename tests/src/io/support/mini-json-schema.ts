/**
 * A tiny JSON Schema checker for exactly the keywords our generated schema uses (type, const,
 * properties, required, additionalProperties, prefixItems/items, min/maxItems, min/maxLength,
 * exclusiveMinimum, maximum, $defs with local $refs for the recursive group node). It lets tests check examples against the published schema without a
 * validator dependency; an unsupported keyword fails loudly so the checker cannot silently pass.
 */
type Schema = Record<string, unknown>;

const SUPPORTED = new Set([
  '$schema',
  'title',
  'description',
  'type',
  'const',
  'properties',
  'required',
  'additionalProperties',
  'propertyNames',
  'prefixItems',
  'items',
  'minItems',
  'maxItems',
  'minLength',
  'maxLength',
  'exclusiveMinimum',
  'maximum',
  'pattern',
  '$defs',
  '$ref',
]);

const typeOf = (v: unknown) =>
  v === null ? 'null' : Array.isArray(v) ? 'array' : Number.isInteger(v) ? 'integer' : typeof v;

/** Problems of `value` against `schema`, each as "path: what". Empty when valid. */
export function checkSchema(schema: Schema, value: unknown, path = '$', root: Schema = schema): string[] {
  for (const k of Object.keys(schema))
    if (!SUPPORTED.has(k)) throw new Error(`unsupported keyword ${k} at ${path}`);
  if (typeof schema.$ref === 'string') {
    const name = /^#\/\$defs\/(.+)$/.exec(schema.$ref)?.[1];
    const target = name ? (root.$defs as Record<string, Schema> | undefined)?.[name] : undefined;
    if (!target) throw new Error(`unresolvable $ref ${schema.$ref} at ${path}`);
    return checkSchema(target, value, path, root);
  }
  const out: string[] = [];
  const t = schema.type as string | undefined;
  const actual = typeOf(value);
  if (t && !(actual === t || (t === 'number' && actual === 'integer')))
    return [`${path}: expected ${t}, got ${actual}`];
  if ('const' in schema && schema.const !== value)
    out.push(`${path}: expected ${JSON.stringify(schema.const)}`);
  if (typeof value === 'string') {
    if (typeof schema.minLength === 'number' && value.length < schema.minLength)
      out.push(`${path}: too short`);
    if (typeof schema.maxLength === 'number' && value.length > schema.maxLength)
      out.push(`${path}: too long`);
    if (typeof schema.pattern === 'string' && !new RegExp(schema.pattern).test(value))
      out.push(`${path}: pattern`);
  }
  if (typeof value === 'number') {
    if (typeof schema.exclusiveMinimum === 'number' && !(value > schema.exclusiveMinimum))
      out.push(`${path}: too small`);
    if (typeof schema.maximum === 'number' && value > schema.maximum) out.push(`${path}: too large`);
  }
  if (Array.isArray(value)) {
    if (typeof schema.minItems === 'number' && value.length < schema.minItems)
      out.push(`${path}: too few items`);
    if (typeof schema.maxItems === 'number' && value.length > schema.maxItems)
      out.push(`${path}: too many items`);
    const prefix = (schema.prefixItems as Schema[] | undefined) ?? [];
    value.forEach((v, i) => {
      const s = i < prefix.length ? prefix[i] : schema.items;
      if (s === false) out.push(`${path}[${i}]: not allowed`);
      else if (s && typeof s === 'object') out.push(...checkSchema(s as Schema, v, `${path}[${i}]`, root));
    });
  }
  if (actual === 'object') {
    const obj = value as Record<string, unknown>;
    const props = (schema.properties as Record<string, Schema> | undefined) ?? {};
    for (const r of (schema.required as string[] | undefined) ?? [])
      if (!(r in obj)) out.push(`${path}.${r}: missing`);
    for (const [k, v] of Object.entries(obj)) {
      if (k in props) out.push(...checkSchema(props[k], v, `${path}.${k}`, root));
      else if (schema.additionalProperties === false) out.push(`${path}.${k}: not allowed`);
      else if (schema.additionalProperties && typeof schema.additionalProperties === 'object')
        out.push(...checkSchema(schema.additionalProperties as Schema, v, `${path}.${k}`, root));
    }
  }
  return out;
}
