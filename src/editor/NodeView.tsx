/**
 * The ONE node component: everything it shows comes from the node type's declaration (NodeDef) —
 * header, typed ports (coloured by PORT_TYPE_INFO, labelled), inline widgets for unconnected
 * inputs and params (only those that matter in the node's set-up, rarely used ones under "More";
 * see node-fields.ts), the evaluation's read-out, and a badge for the node's diagnostics.
 */
import { Handle, type NodeProps, Position, useConnection } from '@xyflow/react';
import { memo } from 'react';
import type { Diagnostic } from '../../nodes/core/diagnostics.ts';
import { portSpec } from '../../nodes/core/port-lookup.ts';
import { canConnect, PORT_TYPE_INFO, type PortType } from '../../nodes/core/ports.ts';
import { stemOf } from '../state/titles.ts';
import { inHandle, outHandle, portOfHandle } from './connection.ts';
import { useEditorActions } from './editor-context.ts';
import { distinctFixes, FixButton } from './FixButton.tsx';
import type { KfNode, KfNodeData } from './flow-model.ts';
import { useKeyboardWireContext } from './keyboard-wire.ts';
import { MoreSection } from './MoreSection.tsx';
import { type NodeField, nodeFields } from './node-fields.ts';
import { hasInlineEditor } from './widgets/inline-editor.ts';
import { InputWidget, ParamWidget, textProblem } from './widgets/ValueWidget.tsx';

/** "source:point:p1" while a wire is dragged from an output of type point on node p1. */
function useWireInProgress(): { side: 'source' | 'target'; type: PortType; nodeId: string } | null {
  const key = useConnection((c) => {
    if (!c.inProgress || !c.fromHandle) return null;
    const data = c.fromNode.data as KfNodeData;
    const port = portOfHandle(c.fromHandle.id);
    const type = portSpec(data.def, c.fromHandle.type === 'source' ? 'outputs' : 'inputs', port)?.type;
    return type ? `${c.fromHandle.type}|${type}|${c.fromNode.id}` : null;
  });
  if (!key) return null;
  const [side, type, nodeId] = key.split('|');
  return { side: side as 'source' | 'target', type: type as PortType, nodeId };
}

const worst = (ds: readonly Diagnostic[]) =>
  ds.some((d) => d.severity === 'error')
    ? 'error'
    : ds.some((d) => d.severity === 'warning')
      ? 'warning'
      : 'info';

export function DiagnosticBadge({ diagnostics }: { diagnostics: readonly Diagnostic[] }) {
  if (diagnostics.length === 0) return null;
  const level = worst(diagnostics);
  return (
    <span
      className={`kf-badge kf-badge--${level}`}
      title={diagnostics.map((d) => `${d.code} ${d.message}`).join('\n')}
      role="img"
      aria-label={`${diagnostics.length} ${level}${diagnostics.length === 1 ? '' : 's'}: ${diagnostics.map((d) => d.message).join('; ')}`}
    >
      {level === 'error' ? '!' : level === 'warning' ? '!' : 'i'}
    </span>
  );
}

function Port({
  nodeId,
  nodeName,
  side,
  port,
  label,
  type,
  doc,
  dim,
}: {
  nodeId: string;
  /** The node as a screen reader names it, so a port is "Line a input", not just "a". */
  nodeName: string;
  side: 'in' | 'out';
  port: string;
  label: string;
  type: PortType | null;
  doc?: string;
  dim: boolean;
}) {
  const info = type ? PORT_TYPE_INFO[type] : null;
  const wire = useKeyboardWireContext();
  const name = `${nodeName} ${label} ${side === 'in' ? 'input' : 'output'}`;
  const picked = wire.pending?.nodeId === nodeId && wire.pending.side === side && wire.pending.port === port;
  return (
    <Handle
      // Focusable so a keyboard can wire: Enter picks the port up, Enter on another lays the wire.
      tabIndex={0}
      role="button"
      aria-label={`${name}, ${type ?? 'unknown'}`}
      aria-pressed={picked}
      onKeyDown={(e) => {
        // A port focused by a press (a wire dragged with the pointer) leaves Space and Enter to the
        // editor (Space opens the palette where the pointer is); keyboard focus wires.
        if (!(e.currentTarget as HTMLElement).dataset.byPointer)
          wire.onPortKey({ nodeId, side, port, name }, e);
      }}
      onPointerDown={(e) => {
        (e.currentTarget as HTMLElement).dataset.byPointer = '1';
      }}
      onBlur={(e) => {
        delete (e.currentTarget as HTMLElement).dataset.byPointer;
      }}
      id={side === 'in' ? inHandle(port) : outHandle(port)}
      type={side === 'in' ? 'target' : 'source'}
      position={side === 'in' ? Position.Left : Position.Right}
      className={`kf-port kf-port--${type ?? 'unknown'}${info?.many ? ' kf-port--many' : ''}${dim ? ' kf-port--dim' : ''}${picked ? ' kf-port--picked' : ''}`}
      style={{ background: info?.color ?? '#666' }}
      title={`${label}: ${type ?? 'unknown'}${info?.many ? ' (takes many wires)' : ''}${doc ? ` — ${doc}` : ''}`}
    />
  );
}

function NodeViewImpl({ id, data, selected }: NodeProps<KfNode>) {
  const { editParam, setHoveredNode, runFix, openGroup } = useEditorActions();
  const wire = useWireInProgress();
  const { node, def, connected, evaluation, diagnostics } = data;
  const nodeName = node.label ?? def?.label ?? node.type;
  const portDiag = (port: string) => diagnostics.filter((d) => d.port === port);

  /** Whether a handle on this node can take the wire being dragged (others dim). */
  const dims = (side: 'in' | 'out', type: PortType | null): boolean => {
    if (!wire) return false;
    if (wire.nodeId === id || !type) return true;
    if (wire.side === 'source') return side === 'out' || !canConnect(wire.type, type);
    return side === 'in' || !canConnect(type, wire.type);
  };

  /** Fields with a diagnostic of their own are shown whatever the set-up, so no problem hides. */
  const fields = def
    ? nodeFields(def, node.params, connected, new Set(diagnostics.flatMap((d) => (d.port ? [d.port] : []))))
    : null;

  const fieldRow = (f: NodeField) => {
    const problems = portDiag(f.name);
    const rowClass = problems.length ? ` kf-row--${worst(problems)}` : '';
    const title = problems.map((d) => d.message).join('\n') || undefined;
    if (f.kind === 'param')
      return (
        <div key={`p-${f.name}`} className={`kf-row kf-row--param${rowClass}`} title={title}>
          <ParamWidget
            name={f.name}
            spec={f.spec}
            value={node.params[f.name]}
            onEdit={editParam(id, f.name)}
            problem={textProblem(problems, f.name)}
          />
        </div>
      );
    const { name: port, spec } = f;
    const widget =
      !connected.has(port) && hasInlineEditor(spec, node.params[port]) ? (
        <InputWidget name={port} spec={spec} value={node.params[port]} onEdit={editParam(id, port)} />
      ) : null;
    return (
      <div key={`i-${port}`} className={`kf-row kf-row--in${rowClass}`} title={title}>
        <Port
          nodeId={id}
          nodeName={nodeName}
          side="in"
          port={port}
          label={spec.label ?? port}
          type={spec.type}
          doc={spec.doc}
          dim={dims('in', spec.type)}
        />
        {widget ?? <span className="kf-row__label">{spec.label ?? port}</span>}
      </div>
    );
  };

  const accent = def?.color ?? '#e5484d';
  return (
    <div
      className={`kf-node${selected ? ' kf-node--selected' : ''}${data.hovered ? ' kf-node--hovered' : ''}${def ? '' : ' kf-node--unknown'}${node.muted ? ' kf-node--muted' : ''}`}
      style={{ '--kf-accent': accent } as React.CSSProperties}
      onPointerEnter={() => setHoveredNode(id)}
      onPointerLeave={() => setHoveredNode(null)}
      data-node-id={id}
      data-node-type={node.type}
    >
      <div className="kf-node__header" title={def?.doc}>
        <span className="kf-node__swatch" />
        {node.label ? (
          <>
            <span className="kf-node__title">{node.label}</span>
            {/* "Line reflection 2" already says its type. */}
            {stemOf(node.label) !== def?.label && (
              <span className="kf-node__type">{def?.label ?? node.type}</span>
            )}
          </>
        ) : (
          <span className="kf-node__title">{def?.label ?? `Unknown “${node.type}”`}</span>
        )}
        {node.muted && (
          <span className="kf-node__muted" title="Muted: skipped (M unmutes)">
            muted
          </span>
        )}
        <DiagnosticBadge diagnostics={diagnostics} />
      </div>
      <div className="kf-node__body">
        {def &&
          Object.entries(def.outputs).map(([port, spec]) => (
            <div key={`o-${port}`} className="kf-row kf-row--out">
              <span className="kf-row__label">{spec.label ?? port}</span>
              <Port
                nodeId={id}
                nodeName={nodeName}
                side="out"
                port={port}
                label={spec.label ?? port}
                type={spec.type}
                doc={spec.doc}
                dim={dims('out', spec.type)}
              />
            </div>
          ))}
        {node.group && (
          <div className="kf-row">
            <button
              type="button"
              className="kf-button nodrag"
              title="Edit the nodes inside (double-click or Enter)"
              onClick={() => openGroup(id)}
            >
              Open group
            </button>
            <span className="kf-row__label">{node.group.nodes.length} nodes</span>
          </div>
        )}
        {fields?.main.map(fieldRow)}
        {fields && fields.more.length > 0 && (
          <MoreSection nodeId={id} count={fields.more.length}>
            {fields.more.map(fieldRow)}
          </MoreSection>
        )}
        {!def && (
          <>
            {data.orphanPorts.outputs.map((port) => (
              <div key={`o-${port}`} className="kf-row kf-row--out">
                <span className="kf-row__label">{port}</span>
                <Port
                  nodeId={id}
                  nodeName={nodeName}
                  side="out"
                  port={port}
                  label={port}
                  type={null}
                  dim={dims('out', null)}
                />
              </div>
            ))}
            {data.orphanPorts.inputs.map((port) => (
              <div key={`i-${port}`} className="kf-row kf-row--in">
                <Port
                  nodeId={id}
                  nodeName={nodeName}
                  side="in"
                  port={port}
                  label={port}
                  type={null}
                  dim={dims('in', null)}
                />
                <span className="kf-row__label">{port}</span>
              </div>
            ))}
            <div className="kf-node__note">This node type is not known; its data is kept.</div>
          </>
        )}
      </div>
      {evaluation?.readout && <div className="kf-node__readout">{evaluation.readout}</div>}
      {distinctFixes(diagnostics).map((fix) => (
        <div key={fix.label} className="kf-node__fix">
          <FixButton fix={fix} onFix={runFix} />
        </div>
      ))}
    </div>
  );
}

export const NodeView = memo(NodeViewImpl);
