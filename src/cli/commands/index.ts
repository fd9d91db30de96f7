/**
 * Every `kleinflow` sub-command, in the order `kleinflow help` lists them. Adding a command =
 * one file in this folder + one line here.
 */
import type { CliCommand } from '../command.ts';
import { checkCommand } from './check.ts';
import { convertCommand } from './convert.ts';
import { glslCommand } from './glsl.ts';
import { meshCommand } from './mesh.ts';
import { renderCommand } from './render.ts';
import { sampleCommand } from './sample.ts';
import { svgCommand } from './svg.ts';

export const COMMANDS: readonly CliCommand[] = [
  renderCommand,
  sampleCommand,
  glslCommand,
  checkCommand,
  convertCommand,
  svgCommand,
  meshCommand,
];
