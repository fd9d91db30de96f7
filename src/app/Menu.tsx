/**
 * A small drop-down menu button (examples, export, and the phone's ☰ menu of every command):
 * keyboard reachable, closes on outside click or Esc. Items may come in titled groups. The arrow
 * keys move through the items as in any menu (↓ on the button opens it at the first item; Home,
 * End), Tab still goes through them in order, and Esc from an item gives the focus back to the button.
 */
import { Fragment, type KeyboardEvent, type ReactNode, useEffect, useRef, useState } from 'react';

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
  const toggle = useRef<HTMLButtonElement>(null);
  /** ↓ on the closed button: the first item takes the focus once the list is there. */
  const focusFirst = useRef(false);
  useEffect(() => {
    if (!open || !focusFirst.current) return;
    focusFirst.current = false;
    menuItems(root.current)[0]?.focus();
  }, [open]);
  useEffect(() => {
    if (!open) return;
    const close = (e: PointerEvent) => root.current?.contains(e.target as Node) || setOpen(false);
    const esc = (e: globalThis.KeyboardEvent) => {
      if (e.key !== 'Escape') return;
      // The focused item goes with the list: the keyboard stays on the menu's button.
      if (root.current?.contains(document.activeElement)) toggle.current?.focus();
      setOpen(false);
    };
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
  /** ↑ ↓ Home End move among the enabled items (from the button too); ↓ on a closed menu opens it. */
  const onKeyDown = (e: KeyboardEvent) => {
    if (!['ArrowDown', 'ArrowUp', 'Home', 'End'].includes(e.key)) return;
    e.preventDefault();
    if (!open) {
      if (e.key !== 'ArrowDown' || e.target !== toggle.current) return;
      focusFirst.current = true;
      setOpen(true);
      return;
    }
    const items = menuItems(root.current);
    const at = items.indexOf(document.activeElement as HTMLButtonElement);
    const last = items.length - 1;
    const next = {
      ArrowDown: at < 0 || at === last ? 0 : at + 1,
      ArrowUp: at <= 0 ? last : at - 1,
      Home: 0,
      End: last,
    }[e.key];
    if (next !== undefined) items[next]?.focus();
  };
  return (
    // biome-ignore lint/a11y/noStaticElementInteractions: the arrow keys of the button and its items (both interactive) bubble here
    <div className="kf-menu" ref={root} onKeyDown={onKeyDown}>
      <button
        ref={toggle}
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

/** The menu's enabled items, in order. */
const menuItems = (root: HTMLElement | null): HTMLButtonElement[] =>
  root ? [...root.querySelectorAll<HTMLButtonElement>('[role="menuitem"]:not(:disabled)')] : [];
