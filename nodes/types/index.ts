/** The registry: every node type, in palette order. Adding a node type = one file + one line here. */
import { createRegistry } from '../core/registry.ts';
import { circleNode } from './circle.ts';
import { circle3ptNode } from './circle-3pt.ts';
import { inversionNode } from './inversion.ts';
import { kaleidoscopeNode } from './kaleidoscope.ts';
import { lineNode } from './line.ts';
import { loxodromicNode } from './loxodromic.ts';
import { mobiusNode } from './mobius.ts';
import { numberNode } from './number.ts';
import { pointNode } from './point.ts';
import { reflectionNode } from './reflection.ts';
import { renderNode } from './render.ts';
import { tileNode } from './tile.ts';

export const NODE_TYPES = [
  numberNode,
  pointNode,
  lineNode,
  circleNode,
  circle3ptNode,
  inversionNode,
  reflectionNode,
  mobiusNode,
  loxodromicNode,
  kaleidoscopeNode,
  tileNode,
  renderNode,
] as const;

export const registry = createRegistry(NODE_TYPES);
