/**
 * The inline editor for one unconnected input (by port type) or one param (by ParamSpec).
 * One place decides which widget a value gets, for the node and the inspector alike.
 */
import type { InputSpec, ParamSpec } from '../../../nodes/core/define-node.ts';
import type { Plane, Sphere, Vec3 } from '../../../nodes/core/scene-3d.ts';
import type { Circle, Line, Vec2 } from '../../../nodes/core/values.ts';
import type { OnEdit } from './edit.ts';
import { isVec2, isVec3 } from './inline-editor.ts';
import { NumberField } from './NumberField.tsx';
import { ColorField, EnumField, TextField, type TextProblem, ToggleField } from './simple-fields.tsx';

const AXES = ['x', 'y', 'z'] as const;

/** A point of the plane or of space: one compact number field per coordinate. */
function PointField<V extends Vec2 | Vec3>({
  label,
  value,
  onEdit,
  title,
}: {
  label: string;
  value: V;
  onEdit: OnEdit<V>;
  title?: string;
}) {
  return (
    <div className="kf-field kf-point" title={title}>
      <span className="kf-field__label">{label}</span>
      <span className={value.length === 3 ? 'kf-point__xyz' : 'kf-point__xy'}>
        {value.map((c, i) => (
          <NumberField
            key={AXES[i]}
            label={`${label} ${AXES[i]}`}
            compact
            value={c}
            spec={{ step: 0.01 }}
            onEdit={(x, f) => onEdit(value.map((old, j) => (j === i ? x : old)) as unknown as V, f)}
          />
        ))}
      </span>
    </div>
  );
}

interface InputProps {
  readonly name: string;
  readonly spec: InputSpec;
  /** The stored (document-form) value, or undefined for the default. */
  readonly value: unknown;
  readonly onEdit: OnEdit<unknown>;
}

/** Editor of an unconnected input; null for types with no inline value (element, tile, image). */
export function InputWidget({ name, spec, value, onEdit }: InputProps) {
  const label = spec.label ?? name;
  const v = value === undefined ? spec.default : value;
  switch (spec.type) {
    case 'number':
      return typeof v === 'number' ? (
        <NumberField label={label} title={spec.doc} value={v} spec={spec} onEdit={onEdit} />
      ) : null;
    case 'point':
      return isVec2(v) ? <PointField label={label} title={spec.doc} value={v} onEdit={onEdit} /> : null;
    case 'color':
      return typeof v === 'string' ? (
        <ColorField label={label} title={spec.doc} value={v} onEdit={onEdit} />
      ) : null;
    case 'line': {
      const line = v as Line | undefined;
      if (!line || !isVec2(line.a) || !isVec2(line.b)) return null;
      return (
        <>
          <PointField label={`${label} a`} value={line.a} onEdit={(a, f) => onEdit({ ...line, a }, f)} />
          <PointField label={`${label} b`} value={line.b} onEdit={(b, f) => onEdit({ ...line, b }, f)} />
        </>
      );
    }
    case 'circle': {
      const circle = v as Circle | undefined;
      if (!circle || !isVec2(circle.c)) return null;
      return (
        <>
          <PointField
            label={`${label} centre`}
            value={circle.c}
            onEdit={(c, f) => onEdit({ ...circle, c }, f)}
          />
          <NumberField
            label={`${label} radius`}
            value={circle.r}
            spec={{ min: 0, step: 0.01 }}
            onEdit={(r, f) => onEdit({ ...circle, r }, f)}
          />
        </>
      );
    }
    case 'point3':
      return isVec3(v) ? <PointField label={label} title={spec.doc} value={v} onEdit={onEdit} /> : null;
    case 'sphere': {
      const sphere = v as Sphere | undefined;
      if (!sphere || !isVec3(sphere.center)) return null;
      return (
        <>
          <PointField
            label={`${label} centre`}
            value={sphere.center}
            onEdit={(center, f) => onEdit({ ...sphere, center }, f)}
          />
          <NumberField
            label={`${label} radius`}
            value={sphere.radius}
            spec={{ min: 0, step: 0.01 }}
            onEdit={(radius, f) => onEdit({ ...sphere, radius }, f)}
          />
        </>
      );
    }
    case 'plane': {
      const plane = v as Plane | undefined;
      if (!plane || !isVec3(plane.point) || !isVec3(plane.normal)) return null;
      return (
        <>
          <PointField
            label={`${label} point`}
            value={plane.point}
            onEdit={(point, f) => onEdit({ ...plane, point }, f)}
          />
          <PointField
            label={`${label} normal`}
            value={plane.normal}
            onEdit={(normal, f) => onEdit({ ...plane, normal }, f)}
          />
        </>
      );
    }
    default:
      return null;
  }
}

interface ParamProps {
  readonly name: string;
  readonly spec: ParamSpec;
  readonly value: unknown;
  readonly onEdit: OnEdit<unknown>;
  /** A diagnostic on this param naming characters of its text (a formula's error), if any. */
  readonly problem?: TextProblem;
}

export function ParamWidget({ name, spec, value, onEdit, problem }: ParamProps) {
  const label = spec.label ?? name;
  switch (spec.kind) {
    case 'boolean':
      return (
        <ToggleField
          label={label}
          title={spec.doc}
          value={typeof value === 'boolean' ? value : spec.default}
          onEdit={onEdit}
        />
      );
    case 'enum':
      return (
        <EnumField
          label={label}
          title={spec.doc}
          value={typeof value === 'string' ? value : spec.default}
          options={spec.options}
          onEdit={onEdit}
        />
      );
    case 'number':
      return (
        <NumberField
          label={label}
          title={spec.doc}
          value={typeof value === 'number' ? value : spec.default}
          spec={spec}
          onEdit={onEdit}
        />
      );
    case 'color':
      return (
        <ColorField
          label={label}
          title={spec.doc}
          value={typeof value === 'string' ? value : spec.default}
          onEdit={onEdit}
        />
      );
    case 'string':
      return (
        <TextField
          label={label}
          title={spec.doc}
          value={typeof value === 'string' ? value : spec.default}
          onEdit={onEdit}
          problem={problem}
        />
      );
  }
}

/** The first of `diagnostics` on param `name` that names characters of its text. */
export function textProblem(
  diagnostics: readonly { port?: string; message: string; span?: readonly [number, number] }[],
  name: string,
): TextProblem | undefined {
  const d = diagnostics.find((x) => x.port === name && x.span);
  return d?.span ? { message: d.message, span: d.span } : undefined;
}
