/**
 * The search palette: type to fuzzy-find a node type (label, id, category, doc), arrow keys to
 * move, Enter to add it where the palette was opened. Pre-filtered when opened by a dropped wire.
 */
import { useMemo, useState } from 'react';
import type { NodeDef } from '../../nodes/core/define-node.ts';
import { PORT_TYPE_INFO } from '../../nodes/core/ports.ts';
import { searchNodeTypes, type WireFilter } from './fuzzy.ts';

interface Props {
  readonly defs: readonly NodeDef[];
  /** Screen position (css px, relative to the page) where the palette opens. */
  readonly at: { x: number; y: number };
  readonly filter?: WireFilter;
  onPick(def: NodeDef): void;
  onClose(): void;
}

export function Palette({ defs, at, filter, onPick, onClose }: Props) {
  const [query, setQuery] = useState('');
  const [active, setActive] = useState(0);
  const results = useMemo(() => searchNodeTypes(defs, query, filter), [defs, query, filter]);

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
            else if (e.key === 'Enter' && results[active]) onPick(results[active]);
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
          {results.map((def, i) => (
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
        </div>
      </div>
    </div>
  );
}
