/**
 * The search palette: type to fuzzy-find a node type (label, id, category, doc), arrow keys to
 * move, Enter to add it where the palette was opened. Pre-filtered when opened by a dropped wire.
 */
import { useMemo, useState } from 'react';
import type { NodeDef } from '../../nodes/core/define-node.ts';
import { PORT_TYPE_INFO } from '../../nodes/core/ports.ts';
import { searchNodeTypes, type WireFilter } from './fuzzy.ts';
import type { SavedGroup } from './tools/my-groups.ts';

interface Props {
  readonly defs: readonly NodeDef[];
  /** Screen position (css px, relative to the page) where the palette opens. */
  readonly at: { x: number; y: number };
  readonly filter?: WireFilter;
  onPick(def: NodeDef): void;
  /** "My groups" (tools/my-groups.ts), listed after the node types whose name matches. */
  readonly saved?: readonly SavedGroup[];
  onPickSaved?(group: SavedGroup): void;
  onClose(): void;
}

export function Palette({ defs, at, filter, onPick, saved = [], onPickSaved, onClose }: Props) {
  const [query, setQuery] = useState('');
  const [active, setActive] = useState(0);
  const types = useMemo(() => searchNodeTypes(defs, query, filter), [defs, query, filter]);
  // A dropped wire asks for a node type that fits it; saved groups are offered on a plain search.
  const groups = useMemo(
    () => (filter ? [] : saved.filter((g) => g.name.toLowerCase().includes(query.trim().toLowerCase()))),
    [saved, query, filter],
  );
  const results = [...types, ...groups];
  const pick = (i: number) => {
    const r = results[i];
    if (!r) return;
    if ('body' in r) onPickSaved?.(r);
    else onPick(r);
  };

  // Keep the palette on screen.
  const left = Math.max(8, Math.min(at.x, window.innerWidth - 360));
  const top = Math.max(8, Math.min(at.y, window.innerHeight - 380));

  return (
    <div className="kf-palette-backdrop" onPointerDown={onClose}>
      <div
        className="kf-palette"
        role="dialog"
        aria-modal="true"
        aria-label="Add node"
        style={{ left, top }}
        onPointerDown={(e) => e.stopPropagation()}
      >
        <input
          // biome-ignore lint/a11y/noAutofocus: the palette exists to be typed into
          autoFocus
          className="kf-palette__input"
          placeholder={filter ? `Nodes that take or give a ${filter.type}…` : 'Add node…'}
          aria-label="Search node types"
          role="combobox"
          aria-expanded="true"
          aria-controls="kf-palette-list"
          value={query}
          onChange={(e) => {
            setQuery(e.target.value);
            setActive(0);
          }}
          onKeyDown={(e) => {
            if (e.key === 'ArrowDown') setActive((a) => Math.min(results.length - 1, a + 1));
            else if (e.key === 'ArrowUp') setActive((a) => Math.max(0, a - 1));
            else if (e.key === 'Enter' && results[active]) pick(active);
            else if (e.key === 'Escape') onClose();
            // The list is walked with the arrows; Tab must not leave the palette for the page behind.
            else if (e.key !== 'Tab') return;
            e.preventDefault();
            e.stopPropagation();
          }}
        />
        {filter && (
          <div className="kf-palette__filter">
            <span className="kf-dot" style={{ background: PORT_TYPE_INFO[filter.type].color }} />
            wire: {filter.type} {filter.from === 'source' ? 'output' : 'input'}
          </div>
        )}
        <div className="kf-palette__list" id="kf-palette-list" role="listbox">
          {results.length === 0 && <div className="kf-palette__empty">No node type matches “{query}”.</div>}
          {types.map((def, i) => (
            <div
              key={def.type}
              ref={i === active ? (el) => el?.scrollIntoView({ block: 'nearest' }) : undefined}
              role="option"
              tabIndex={-1}
              aria-selected={i === active}
              className="kf-palette__item"
              onPointerEnter={() => setActive(i)}
              onClick={() => onPick(def)}
              onKeyDown={(e) => e.key === 'Enter' && onPick(def)}
            >
              <span className="kf-dot" style={{ background: def.color }} />
              <span className="kf-palette__label">{def.label}</span>
              <span className="kf-palette__category">{def.category}</span>
              <span className="kf-palette__doc">{def.doc}</span>
            </div>
          ))}
          {groups.length > 0 && (
            <div className="kf-palette__heading" role="presentation">
              My groups
            </div>
          )}
          {groups.map((g, j) => {
            const i = types.length + j;
            return (
              <div
                key={`my-${g.name}`}
                role="option"
                tabIndex={-1}
                aria-selected={i === active}
                className="kf-palette__item"
                onPointerEnter={() => setActive(i)}
                onClick={() => pick(i)}
                onKeyDown={(e) => e.key === 'Enter' && pick(i)}
              >
                <span className="kf-dot" style={{ background: '#8d99ae' }} />
                <span className="kf-palette__label">{g.name}</span>
                <span className="kf-palette__category">My groups</span>
                <span className="kf-palette__doc">A saved group of {g.body.nodes.length} nodes.</span>
              </div>
            );
          })}
        </div>
      </div>
    </div>
  );
}
