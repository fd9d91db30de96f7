/** The registry: every node type, in palette order. Adding a node type = one file + one line here. */
import { createRegistry } from '../core/registry.ts';
import { circularMotionNode, sineNode, timeNode } from './animation.ts';
import { boxFoldNode } from './box-fold.ts';
import { circleNode } from './circle.ts';
import { circle3ptNode } from './circle-3pt.ts';
import { circleCenterPointNode } from './circle-center-point.ts';
import { colorNode, cosinePaletteNode } from './colour.ts';
import { compoundLoxodromic3dNode } from './compound-loxodromic-3d.ts';
import { compoundParabolic3dNode } from './compound-parabolic-3d.ts';
import { formulaNode } from './formula.ts';
import { hyperbolicPolygonNode } from './hyperbolic-polygon.ts';
import { imageNode } from './image.ts';
import { intersectCirclesNode, intersectLineCircleNode, intersectLinesNode } from './intersections.ts';
import { inversionNode } from './inversion.ts';
import { kMirrorNode } from './k-mirror.ts';
import { kaleidoscopeNode } from './kaleidoscope.ts';
import { latticeNode } from './lattice.ts';
import { lineNode } from './line.ts';
import { parallelLineNode, perpendicularBisectorNode, perpendicularLineNode } from './line-constructions.ts';
import { loxodromicNode } from './loxodromic.ts';
import { maskitNode } from './maskit.ts';
import { maskitSliceNode } from './maskit-slice.ts';
import { angleNode, distanceNode } from './measures.ts';
import { mobiusNode } from './mobius.ts';
import { mobius3dNode } from './mobius-3d.ts';
import { mobiusMatrixNode } from './mobius-matrix.ts';
import { numberNode } from './number.ts';
import { planeNode } from './plane.ts';
import { planeReflectionNode } from './plane-reflection.ts';
import { pointNode } from './point.ts';
import { point3dNode } from './point-3d.ts';
import { invertPointNode, midpointNode, reflectPointNode } from './point-constructions.ts';
import { quaternionGroupNode } from './quaternion-group.ts';
import { recipeNode } from './recipe.ts';
import { rectangleKaleidoscopeNode } from './rectangle-kaleidoscope.ts';
import { reflectionNode } from './reflection.ts';
import { renderNode } from './render.ts';
import { render3dNode } from './render-3d.ts';
import { rotationNode } from './rotation.ts';
import { seedBoxNode } from './seed-box.ts';
import { seedShapeNode } from './seed-shape.ts';
import { seedSolidNode } from './seed-solid.ts';
import { seedSphereNode } from './seed-sphere.ts';
import { seedDiskNode, seedImageNode } from './seeds.ts';
import { sphairahedronNode } from './sphairahedron.ts';
import { sphairahedronSpaceNode } from './sphairahedron-space.ts';
import { sphereNode } from './sphere.ts';
import { sphere4ptNode } from './sphere-4pt.ts';
import { sphereInversionNode } from './sphere-inversion.ts';
import { spiralSimilarityNode } from './spiral-similarity.ts';
import { glideReflectionNode, parallelMirrorsNode, translationNode } from './strip.ts';
import { tileNode } from './tile.ts';

export const NODE_TYPES = [
  numberNode,
  pointNode,
  lineNode,
  circleNode,
  circle3ptNode,
  circleCenterPointNode,
  midpointNode,
  intersectLinesNode,
  intersectLineCircleNode,
  intersectCirclesNode,
  perpendicularBisectorNode,
  parallelLineNode,
  perpendicularLineNode,
  invertPointNode,
  reflectPointNode,
  angleNode,
  distanceNode,
  formulaNode,
  inversionNode,
  reflectionNode,
  mobiusNode,
  loxodromicNode,
  mobiusMatrixNode,
  maskitNode,
  maskitSliceNode,
  recipeNode,
  translationNode,
  latticeNode,
  glideReflectionNode,
  rotationNode,
  spiralSimilarityNode,
  kaleidoscopeNode,
  kMirrorNode,
  rectangleKaleidoscopeNode,
  parallelMirrorsNode,
  hyperbolicPolygonNode,
  tileNode,
  seedDiskNode,
  seedImageNode,
  seedShapeNode,
  imageNode,
  colorNode,
  cosinePaletteNode,
  timeNode,
  sineNode,
  circularMotionNode,
  renderNode,
  point3dNode,
  sphereNode,
  sphere4ptNode,
  planeNode,
  sphereInversionNode,
  planeReflectionNode,
  mobius3dNode,
  compoundLoxodromic3dNode,
  compoundParabolic3dNode,
  quaternionGroupNode,
  boxFoldNode,
  seedSphereNode,
  seedBoxNode,
  seedSolidNode,
  sphairahedronNode,
  sphairahedronSpaceNode,
  render3dNode,
] as const;

export const registry = createRegistry(NODE_TYPES);
