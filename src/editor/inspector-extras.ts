/**
 * Extra inspector content the app adds for some nodes (e.g. the image node's camera and video
 * controls, which need the page's media that the editor layer does not know about).
 */
import { createContext, type ReactNode } from 'react';
import type { GraphNode } from '../../nodes/graph/document.ts';

export type InspectorExtras = (node: GraphNode) => ReactNode;

export const InspectorExtrasContext = createContext<InspectorExtras | null>(null);
