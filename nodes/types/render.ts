import { defineNode } from '../core/define-node.ts';
import { diag } from '../core/diagnostics.ts';
import { LIMITS } from '../core/limits.ts';
import type { SceneElement } from '../core/scene-elements.ts';
import { DEFAULT_TILE } from '../core/tile-spec.ts';
import { sceneGenerators, schottkyDisks } from '../geometry/group-generators.ts';
import { elementInput } from './shared.ts';

export const renderNode = defineNode({
  type: 'render',
  version: 1,
  label: 'Render',
  category: 'Output',
  color: '#ffffff',
  doc: 'The picture: runs the IIS with every element wired in (tested in graph order) and colours it with the tile.',
  inputs: {
    elements: elementInput('elements'),
    tile: { type: 'tile', label: 'tile', optional: true },
    clip: {
      type: 'circle',
      label: 'clip',
      optional: true,
      doc: 'only draw inside this disk (e.g. the Poincaré disk)',
    },
    cayleyBase: {
      type: 'point',
      label: 'Cayley base',
      optional: true,
      doc: "the Cayley graph's base point in the fundamental tile (unwired: the tile's most interior point in the view)",
    },
  },
  outputs: {},
  params: {
    maxIterations: {
      kind: 'number',
      default: LIMITS.defaultMaxIterations,
      min: 1,
      max: LIMITS.maxIterations,
      integer: true,
      label: 'max iterations',
    },
    samples: {
      kind: 'number',
      default: 4,
      min: 1,
      max: LIMITS.maxSamples,
      integer: true,
      label: 'samples / pixel',
    },
    cayleyDepth: {
      kind: 'number',
      default: 0,
      min: 0,
      max: LIMITS.maxCayleyDepth,
      integer: true,
      label: 'Cayley graph depth',
      doc: 'draw the Cayley graph over the tiling: tile centres joined by one edge per generator, this many steps deep (0: off)',
    },
    limitSetDfs: {
      kind: 'boolean',
      default: false,
      label: 'limit set (depth-first)',
      doc: "draw the limit set exactly, by depth-first search of the group's words down to a pixel (Schottky-type groups: inversions, Möbius generators)",
    },
  },
  evaluate: ({ inputs, params }) => {
    let elements = inputs.elements;
    const diagnostics = [];
    if (elements.length > LIMITS.maxElements) {
      // A warning: the first maxElements still draw (an error would withhold the whole render).
      diagnostics.push({
        ...diag('tooManyElements', { port: 'elements' }, elements.length, LIMITS.maxElements),
        severity: 'warning' as const,
      });
      elements = elements.slice(0, LIMITS.maxElements);
    }
    if (elements.length === 0)
      diagnostics.push({
        ...diag('clamped', { port: 'elements' }, 'no elements wired in: the whole plane is the tile'),
        severity: 'info' as const,
      });
    diagnostics.push(...figureProblems(elements, params.cayleyDepth > 0, params.limitSetDfs));
    return {
      outputs: {},
      diagnostics,
      readout: `${elements.length} element${elements.length === 1 ? '' : 's'}`,
      render: {
        elements,
        tile: inputs.tile ?? DEFAULT_TILE,
        maxIterations: params.maxIterations,
        samples: params.samples,
        clip: inputs.clip ?? null,
        figures: {
          cayleyDepth: params.cayleyDepth,
          cayleyBase: inputs.cayleyBase ?? null,
          limitSetDfs: params.limitSetDfs,
        },
      },
    };
  },
});

/**
 * Why a figure the render node is asked for cannot be drawn (a KF402 warning on the render node; the
 * picture itself is unaffected): a group the figures do not take, or not Schottky-type for the
 * depth-first search.
 */
function figureProblems(elements: readonly SceneElement[], cayley: boolean, dfs: boolean) {
  if (!cayley && !dfs) return [];
  const warn = (what: string, problem: string) => [
    { ...diag('clamped', {}, `${what} not drawn: ${problem}`), severity: 'warning' as const },
  ];
  const found = sceneGenerators({ elements });
  if (!found.ok) {
    const what =
      cayley && dfs
        ? 'Cayley graph and limit set (depth-first)'
        : cayley
          ? 'Cayley graph'
          : 'limit set (depth-first)';
    return warn(what, found.message);
  }
  const schottky = dfs ? schottkyDisks(found.generators) : null;
  return schottky && !schottky.ok ? warn('limit set (depth-first)', schottky.message) : [];
}
