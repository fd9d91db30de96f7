/**
 * The inline editor for one unconnected input (by port type) or one param (by ParamSpec).
 * One place decides which widget a value gets, for the node and the inspector alike.
 */
import type { InputSpec, ParamSpec } from '../../../nodes/core/define-node.ts';
import type { Circle, Line, Vec2 } from '../../../nodes/core/values.ts';
import type { OnEdit } from './edit.ts';
import { isVec2 } from './inline-editor.ts';
import { NumberField } from './NumberField.tsx';
import { ColorField, EnumField, ToggleField } from './simple-fields.tsx';

function PointField({
  label,
  value,
  onEdit,
  title,
}: {
  label: string;
  value: Vec2;
  onEdit: OnEdit<Vec2>;
  title?: string;
}) {
  return (
    <div className="kf-field kf-point" title={title}>
      <span className="kf-field__label">{label}</span>
      <span className="kf-point__xy">
        <NumberField
          label={`${label} x`}
          compact
          value={value[0]}
          spec={{ step: 0.01 }}
          onEdit={(x, f) => onEdit([x, value[1]], f)}
        />
        <NumberField
          label={`${label} y`}
          compact
          value={value[1]}
          spec={{ step: 0.01 }}
          onEdit={(y, f) => onEdit([value[0], y], f)}
        />
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
    default:
      return null;
  }
}

interface ParamProps {
  readonly name: string;
  readonly spec: ParamSpec;
  readonly value: unknown;
  readonly onEdit: OnEdit<unknown>;
}

export function ParamWidget({ name, spec, value, onEdit }: ParamProps) {
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
        <label className="kf-field nodrag" title={spec.doc}>
          <span className="kf-field__label">{label}</span>
          <input
            className="kf-input"
            aria-label={label}
            defaultValue={typeof value === 'string' ? value : spec.default}
            onBlur={(e) => onEdit(e.target.value, true)}
          />
        </label>
      );
  }
}
