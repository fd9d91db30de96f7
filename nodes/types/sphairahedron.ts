/**
 * The sphairahedron node (paper §5.3, Figs. 25–29): the inversions in the faces of a cube-type
 * sphairahedron and the seed whose orbit draws its limit set — the quasi-sphere (finite form) or
 * the fractal terrain (infinite form). Every type Nakamura–Ahara list (cube A–E, H, I, pentahedral
 * prism A–F, cake A–C). Mathematics: docs/math-3d.md "Sphairahedra (paper §5.3)".
 */
import { defineNode } from '../core/define-node.ts';
import { diag } from '../core/diagnostics.ts';
import type { NodeElement3d, Overlay3dShape, Seed3d } from '../core/scene-3d.ts';
import {
  finiteElements,
  finiteSphairahedron,
  infiniteElements,
  infiniteSeedBox,
  infiniteSphairahedron,
} from '../geometry/space/sphairahedron.ts';
import { outsideWarning } from '../geometry/space/sphairahedron-space.ts';
import { type SphairahedronTile, sphairahedronTile } from '../geometry/space/sphairahedron-tile.ts';
import { SPHAIRAHEDRON_TYPE_IDS, sphairahedronTypeById } from '../geometry/space/sphairahedron-types.ts';
import { fail, fmt } from './shared.ts';
import { point3Input, radiusTo, sphereHandles } from './space-shared.ts';

/** Version-1 type ids whose angle table is a published type's, exactly (checked by a test). */
export const RENAMED_IN_V2: Readonly<Record<string, string>> = {
  'cube-333-a': 'cube-a',
  'cube-244-a': 'cube-h',
  'prism-333-a': 'prism-a',
  'prism-333-b': 'prism-b',
  'prism-244-a': 'prism-f',
};

export const sphairahedronNode = defineNode({
  type: 'sphairahedron',
  version: 2,
  label: 'Sphairahedron',
  category: '3D',
  color: '#7e57c2',
  doc: 'The inversions in the faces of a sphairahedron (a polyhedron with spherical faces, every dihedral angle π/n; the cube, pentahedral prism and cake types of Nakamura–Ahara) and a seed whose orbit draws its limit set: the quasi-sphere (finite: the faces inverted in a sphere you can drag) or a fractal terrain (infinite: a prism of planes closed by spheres).',
  // Version 2 took the published type names (docs/math-3d.md "The published types"); the first
  // table's entries with a published twin of the same angles are renamed to it.
  migrations: {
    1: (params) => {
      const renamed = RENAMED_IN_V2[String(params.shape)];
      return renamed ? { ...params, shape: renamed } : params;
    },
  },
  inputs: {
    zb: {
      type: 'number',
      label: 'zb',
      default: 0,
      step: 0.01,
      doc: 'height of the second sphere (cube, cake) or of the central sphere (pentahedral prism); the first is at 0',
    },
    zc: {
      type: 'number',
      label: 'zc',
      default: 0,
      step: 0.01,
      doc: 'height of the third sphere (cube types only)',
    },
    center: point3Input(
      'inversion centre',
      0,
      0,
      1.5,
      'centre of the inversion sphere that makes the finite form; it must lie above the spheres, inside the prism',
    ),
    radius: {
      type: 'number',
      label: 'inversion radius',
      default: 1.5,
      step: 0.01,
      doc: 'radius of the inversion sphere (the finite form’s size)',
    },
    color: { type: 'color', label: 'colour', default: '#e8c170' },
  },
  outputs: {
    elements: { type: 'element3', label: 'elements' },
    seed: { type: 'seed3', label: 'seed', doc: 'the far side of the limit set: its orbit is drawn' },
    tile: {
      type: 'seed3',
      label: 'tile',
      doc: 'the sphairahedron itself as a solid (Fig. 25): alone, the tile; with the elements, the tiling, grown by max iterations (Figs. 27–28)',
    },
  },
  params: {
    shape: {
      kind: 'enum',
      default: 'cube-a',
      options: SPHAIRAHEDRON_TYPE_IDS,
      label: 'type',
      doc: 'cube A–I (six faces: three planes, three spheres), pentahedral prism A–F (five: three planes, two spheres) or cake A–C (six: four planes, two spheres); the prism (333, 244, 236: its angles π/n) and the dihedral angles of the spheres',
    },
    form: {
      kind: 'enum',
      default: 'finite',
      options: ['finite', 'infinite'],
      label: 'form',
      doc: 'finite: inverted in the inversion sphere, the quasi-sphere; infinite: the prism with a vertex at infinity, a fractal terrain',
    },
  },
  evaluate: ({ inputs, params, nodeId }) => {
    const type = sphairahedronTypeById(params.shape);
    if (!type) return fail(`unknown sphairahedron type "${params.shape}"`);
    const inf = infiniteSphairahedron(type, inputs.zb, inputs.zc);
    if (!inf.ok) return fail(inf.error);
    const tag = (es: ReturnType<typeof infiniteElements>): NodeElement3d[] =>
      es.map((e) => ({ ...e, nodeId }));
    // The tile is the fundamental domain itself: `clipped`, so render-3d does not check it lies in it.
    const tileSeed = (tile: SphairahedronTile): Seed3d => ({
      kind: 'tile',
      nodeId,
      tile,
      color: inputs.color,
      clipped: true,
    });
    const radii = inf.value.spheres.map((s) => fmt(s.radius)).join(', ');
    // Outside the parameter space but with every face: drawn on purpose (bridges, tunnels).
    const outside = outsideWarning(type, inf.value.outside);
    const diagnostics = outside ? [diag('outsideSphairahedronSpace', { port: 'zb' }, outside)] : [];
    if (params.form === 'infinite') {
      const box = infiniteSeedBox(inf.value);
      const seed: Seed3d = { kind: 'box', nodeId, ...box, color: inputs.color, clipped: true };
      const tile = tileSeed(sphairahedronTile(inf.value, null));
      return {
        outputs: { elements: tag(infiniteElements(inf.value)), seed, tile },
        readout: `sphere radii ${radii}; floor at z = ${fmt(inf.value.floorTop)}`,
        diagnostics,
      };
    }
    const fin = finiteSphairahedron(inf.value, { center: inputs.center, radius: inputs.radius });
    if (!fin.ok) return fail(fin.error);
    const seed: Seed3d = {
      kind: 'sphere',
      nodeId,
      sphere: fin.value.seed,
      color: inputs.color,
      clipped: true,
    };
    const tile = tileSeed(sphairahedronTile(inf.value, { center: inputs.center, radius: inputs.radius }));
    return {
      outputs: { elements: tag(finiteElements(fin.value)), seed, tile },
      readout: `sphere radii ${radii} (before inversion)`,
      diagnostics,
    };
  },
  overlay3d: ({ inputs, params }, out) => {
    const faces: Overlay3dShape[] = out.elements.flatMap((e): Overlay3dShape[] =>
      e.kind === 'sphere-inversion'
        ? [{ shape: 'sphere', sphere: e.sphere }]
        : e.kind === 'plane-reflection'
          ? [{ shape: 'plane', plane: e.plane }]
          : [],
    );
    return params.form === 'finite'
      ? [...faces, { shape: 'sphere', sphere: { center: inputs.center, radius: Math.max(0, inputs.radius) } }]
      : faces;
  },
  handles3d: ({ inputs, params }) =>
    params.form === 'finite'
      ? sphereHandles({ center: inputs.center, radius: Math.max(0, inputs.radius) })
      : [],
  drag3d: (handle, to, ctx) =>
    handle === 'center' ? { center: [...to] } : { radius: radiusTo(ctx.inputs.center, to) },
});
