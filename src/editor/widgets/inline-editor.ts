/** Which unconnected inputs get an inline editor on the node (pure: the layout estimate uses it too). */
import type { InputSpec } from '../../../nodes/core/define-node.ts';
import type { Plane, Sphere, Vec3 } from '../../../nodes/core/scene-3d.ts';
import type { Circle, Line, Vec2 } from '../../../nodes/core/values.ts';

export const isVec2 = (v: unknown): v is Vec2 =>
  Array.isArray(v) && v.length === 2 && typeof v[0] === 'number' && typeof v[1] === 'number';

export const isVec3 = (v: unknown): v is Vec3 =>
  Array.isArray(v) && v.length === 3 && v.every((c) => typeof c === 'number');

/** Whether an unconnected input gets an inline editor (types with a value and a usable default). */
export function hasInlineEditor(spec: InputSpec, value: unknown): boolean {
  const v = value === undefined ? spec.default : value;
  switch (spec.type) {
    case 'number':
      return typeof v === 'number';
    case 'point':
      return isVec2(v);
    case 'color':
      return typeof v === 'string';
    case 'line':
      return isVec2((v as Line | undefined)?.a) && isVec2((v as Line | undefined)?.b);
    case 'circle':
      return isVec2((v as Circle | undefined)?.c) && typeof (v as Circle).r === 'number';
    case 'point3':
      return isVec3(v);
    case 'sphere':
      return isVec3((v as Sphere | undefined)?.center) && typeof (v as Sphere).radius === 'number';
    case 'plane':
      return isVec3((v as Plane | undefined)?.point) && isVec3((v as Plane).normal);
    default:
      return false;
  }
}
