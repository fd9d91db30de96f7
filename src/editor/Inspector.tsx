/**
 * The inspector for the selected node: its doc, an editable label, every input (wired or inline)
 * and param that matters in the node's set-up (field-visibility.ts; "More" fields included), the
 * read-out and the full list of its diagnostics.
 */
import { useContext, useEffect, useState } from 'react';
import type { Diagnostic } from '../../nodes/core/diagnostics.ts';
import { isFieldShown } from '../../nodes/core/field-visibility.ts';
import { PORT_TYPE_INFO } from '../../nodes/core/ports.ts';
import type { GraphNode } from '../../nodes/graph/document.ts';
import type { NodeEvaluation } from '../../nodes/graph/evaluate.ts';
import { nodeDef } from '../../nodes/graph/group-def.ts';
import { useEditorActions } from './editor-context.ts';
import { FixButton } from './FixButton.tsx';
import { InspectorExtrasContext } from './inspector-extras.ts';
import { SaveGroup } from './tools/SaveGroup.tsx';
import { hasInlineEditor } from './widgets/inline-editor.ts';
import { InputWidget, ParamWidget, textProblem } from './widgets/ValueWidget.tsx';

interface Props {
  readonly node: GraphNode;
  readonly connected: ReadonlySet<string>;
  readonly evaluation: NodeEvaluation | undefined;
  readonly diagnostics: readonly Diagnostic[];
  onLabel(label: string): void;
  /** Mutes or unmutes the node (one undo step). */
  onMute(muted: boolean): void;
  onClose(): void;
}

export function Inspector({ node, connected, evaluation, diagnostics, onLabel, onMute, onClose }: Props) {
  const { registry, editParam, runFix } = useEditorActions();
  const def = nodeDef(registry, node);
  const extras = useContext(InspectorExtrasContext);
  const [label, setLabel] = useState(node.label ?? '');
  useEffect(() => setLabel(node.label ?? ''), [node.label]);
  // Only the fields that matter in this set-up (and any with a problem of its own), as on the node.
  const withProblem = new Set(diagnostics.flatMap((d) => (d.port ? [d.port] : [])));
  const shown = (name: string) =>
    withProblem.has(name) || (!!def && isFieldShown(def, name, node.params, connected));
  const inputs = def ? Object.entries(def.inputs).filter(([name]) => shown(name)) : [];
  const params = def ? Object.entries(def.params).filter(([name]) => shown(name)) : [];

  return (
    // tabIndex −1: the panel itself takes the focus when it opens from the keyboard (InspectorDock).
    <aside className="kf-inspector" aria-label="Inspector" tabIndex={-1}>
      <header className="kf-inspector__header">
        <span className="kf-dot" style={{ background: def?.color ?? '#e5484d' }} />
        <h2>{def?.label ?? node.type}</h2>
        <code className="kf-inspector__id">{node.id}</code>
        <button
          type="button"
          className={`kf-button${node.muted ? ' kf-button--active' : ''}`}
          aria-pressed={node.muted === true}
          title="Skip this node: its elements leave the picture (M)"
          onClick={() => onMute(!node.muted)}
        >
          Mute node
        </button>
        <button type="button" className="kf-icon-button" aria-label="Close inspector" onClick={onClose}>
          ×
        </button>
      </header>
      <div className="kf-inspector__scroll">
        {def && <p className="kf-inspector__doc">{def.doc}</p>}
        <label className="kf-field">
          <span className="kf-field__label">label</span>
          <input
            className="kf-input"
            aria-label="Node label"
            placeholder="(none)"
            value={label}
            onChange={(e) => setLabel(e.target.value)}
            onBlur={() => label !== (node.label ?? '') && onLabel(label)}
            onKeyDown={(e) => e.key === 'Enter' && (e.target as HTMLInputElement).blur()}
          />
        </label>
        {node.group && <SaveGroup node={node} />}
        {inputs.length > 0 && <h3>Inputs</h3>}
        {def &&
          inputs.map(([port, spec]) => (
            <div key={port} className="kf-inspector__item">
              {connected.has(port) || !hasInlineEditor(spec, node.params[port]) ? (
                <div className="kf-field">
                  <span className="kf-field__label">{spec.label ?? port}</span>
                  <span className="kf-inspector__wired">
                    <span className="kf-dot" style={{ background: PORT_TYPE_INFO[spec.type].color }} />
                    {connected.has(port) ? `wired ${spec.type}` : `${spec.type} (wire one in)`}
                  </span>
                </div>
              ) : (
                <InputWidget
                  name={port}
                  spec={spec}
                  value={node.params[port]}
                  onEdit={editParam(node.id, port)}
                />
              )}
              {spec.doc && <p className="kf-inspector__hint">{spec.doc}</p>}
            </div>
          ))}
        {params.length > 0 && <h3>Settings</h3>}
        {def &&
          params.map(([name, spec]) => (
            <div key={name} className="kf-inspector__item">
              <ParamWidget
                name={name}
                spec={spec}
                value={node.params[name]}
                onEdit={editParam(node.id, name)}
                problem={textProblem(diagnostics, name)}
              />
              {spec.doc && <p className="kf-inspector__hint">{spec.doc}</p>}
            </div>
          ))}
        {extras?.(node)}
        {evaluation?.readout && (
          <>
            <h3>Read-out</h3>
            <p className="kf-inspector__readout">{evaluation.readout}</p>
          </>
        )}
        <h3>Diagnostics</h3>
        {diagnostics.length === 0 ? (
          <p className="kf-inspector__ok">No problems.</p>
        ) : (
          <ul className="kf-diag-list">
            {diagnostics.map((d) => (
              <li key={`${d.code}-${d.port ?? ''}-${d.message}`} className={`kf-diag kf-diag--${d.severity}`}>
                <code>{d.code}</code> {d.message}
                {d.fix && (
                  <>
                    {' '}
                    <FixButton fix={d.fix} onFix={runFix} />
                  </>
                )}
              </li>
            ))}
          </ul>
        )}
      </div>
    </aside>
  );
}
