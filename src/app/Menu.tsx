/**
 * A small drop-down menu button (examples, export, and the phone's ☰ menu of every command):
 * keyboard reachable, closes on outside click or Esc. Items may come in titled groups.
 */
import { Fragment, type ReactNode, useEffect, useRef, useState } from 'react';

export interface MenuItem {
  readonly label: string;
  readonly hint?: string;
  readonly disabled?: boolean;
  onSelect(): void;
}

export interface MenuGroup {
  readonly label: string;
  readonly items: readonly MenuItem[];
}

interface Props {
  label: ReactNode;
  /** Items without a heading; or `groups`. */
  items?: readonly MenuItem[];
  groups?: readonly MenuGroup[];
  title?: string;
  /** The button's accessible name when `label` is an icon. */
  ariaLabel?: string;
  /** Opens towards the left (a menu at the right edge of the window). */
  alignEnd?: boolean;
}

export function Menu({ label, items = [], groups, title, ariaLabel, alignEnd = false }: Props) {
  const [open, setOpen] = useState(false);
  const root = useRef<HTMLDivElement>(null);
  useEffect(() => {
    if (!open) return;
    const close = (e: PointerEvent) => root.current?.contains(e.target as Node) || setOpen(false);
    const esc = (e: KeyboardEvent) => e.key === 'Escape' && setOpen(false);
    window.addEventListener('pointerdown', close);
    window.addEventListener('keydown', esc);
    return () => {
      window.removeEventListener('pointerdown', close);
      window.removeEventListener('keydown', esc);
    };
  }, [open]);
  const button = (item: MenuItem) => (
    <button
      type="button"
      role="menuitem"
      key={item.label}
      className="kf-menu__item"
      disabled={item.disabled}
      onClick={() => {
        setOpen(false);
        item.onSelect();
      }}
    >
      <span>{item.label}</span>
      {item.hint && <span className="kf-menu__hint">{item.hint}</span>}
    </button>
  );
  return (
    <div className="kf-menu" ref={root}>
      <button
        type="button"
        className="kf-button"
        aria-haspopup="menu"
        aria-expanded={open}
        aria-label={ariaLabel}
        title={title}
        onClick={() => setOpen(!open)}
      >
        {label} <span className="kf-caret">▾</span>
      </button>
      {open && (
        <div className={`kf-menu__list${alignEnd ? ' kf-menu__list--end' : ''}`} role="menu">
          {items.map(button)}
          {groups?.map((g) => (
            <Fragment key={g.label}>
              <div className="kf-menu__group" role="presentation">
                {g.label}
              </div>
              {g.items.map(button)}
            </Fragment>
          ))}
        </div>
      )}
    </div>
  );
}
