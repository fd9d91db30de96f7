/**
 * The top bar: document title, examples, file actions, export, present, undo/redo, play and help.
 * On a phone-narrow window every command but Present moves into one ☰ menu (commandGroups).
 */
import { useEffect, useState } from 'react';
import { Menu, type MenuGroup, type MenuItem } from './Menu.tsx';
import { useNarrow } from './use-narrow.ts';

interface Props {
  readonly title: string;
  readonly undoLabel: string | null;
  readonly redoLabel: string | null;
  readonly playing: boolean;
  readonly exportItems: readonly MenuItem[];
  onTitle(title: string): void;
  onExamples(): void;
  onNew(): void;
  onOpen(): void;
  /** The Recent documents this browser saved (any tab). */
  onRecent(): void;
  onSave(): void;
  onUndo(): void;
  onRedo(): void;
  onPlay(): void;
  onHelp(): void;
  onPresent(): void;
  /** Inspect mode ("Explain this pixel"): a click on the picture traces that pixel. */
  readonly inspecting: boolean;
  onInspect(): void;
}

/**
 * Every toolbar command but Present, in groups, for the phone's menu. No keyboard hints (Ctrl S,
 * Alt click, ?): this menu is the narrow, touch layout's, where there is usually no keyboard.
 */
function commandGroups(p: Props): MenuGroup[] {
  return [
    {
      label: 'File',
      items: [
        { label: 'Examples…', hint: 'gallery', onSelect: p.onExamples },
        { label: 'New', hint: 'empty graph', onSelect: p.onNew },
        { label: 'Open…', onSelect: p.onOpen },
        { label: 'Recent…', onSelect: p.onRecent },
        { label: 'Save', onSelect: p.onSave },
      ],
    },
    {
      label: 'Edit',
      items: [
        { label: 'Undo', hint: p.undoLabel ?? undefined, disabled: !p.undoLabel, onSelect: p.onUndo },
        { label: 'Redo', hint: p.redoLabel ?? undefined, disabled: !p.redoLabel, onSelect: p.onRedo },
      ],
    },
    {
      label: 'View',
      items: [
        { label: p.playing ? 'Pause animation' : 'Play animation', onSelect: p.onPlay },
        {
          label: p.inspecting ? 'Stop inspecting' : 'Inspect a pixel',
          onSelect: p.onInspect,
        },
        { label: 'Help', onSelect: p.onHelp },
      ],
    },
    { label: 'Export', items: p.exportItems },
  ];
}

function PresentButton({ onPresent }: Pick<Props, 'onPresent'>) {
  return (
    <button
      type="button"
      className="kf-button kf-button--present"
      onClick={onPresent}
      title="Present the construction step by step (Esc leaves)"
    >
      Present
    </button>
  );
}

export function TopBar(p: Props) {
  const [title, setTitle] = useState(p.title);
  useEffect(() => setTitle(p.title), [p.title]);
  const narrow = useNarrow();
  return (
    <header className={narrow ? 'kf-topbar kf-topbar--narrow' : 'kf-topbar'}>
      <div className="kf-brand">
        <svg viewBox="0 0 24 24" width="20" height="20" aria-hidden="true">
          <circle cx="12" cy="12" r="9.5" fill="none" stroke="currentColor" strokeWidth="1.5" />
          <circle cx="12" cy="7" r="3.2" fill="#e85d75" />
          <circle cx="7.7" cy="14.5" r="3.2" fill="#5b8def" />
          <circle cx="16.3" cy="14.5" r="3.2" fill="#f2c14e" />
        </svg>
        <span>Kleinflow</span>
      </div>
      <input
        className="kf-title"
        aria-label="Document title"
        value={title}
        onChange={(e) => setTitle(e.target.value)}
        onBlur={() => title !== p.title && p.onTitle(title)}
        onKeyDown={(e) => e.key === 'Enter' && (e.target as HTMLInputElement).blur()}
      />
      {narrow ? (
        <nav className="kf-toolbar" aria-label="Document">
          <PresentButton onPresent={p.onPresent} />
          <Menu label="☰" ariaLabel="Menu" title="Every command" groups={commandGroups(p)} alignEnd />
        </nav>
      ) : (
        <nav className="kf-toolbar" aria-label="Document">
          <button
            type="button"
            className="kf-button"
            onClick={p.onExamples}
            aria-haspopup="dialog"
            title="Open an example graph (a gallery you can search)"
          >
            Examples
          </button>
          <button type="button" className="kf-button" onClick={p.onNew} title="Start an empty graph">
            New
          </button>
          <button
            type="button"
            className="kf-button"
            onClick={p.onOpen}
            title="Open a .kleinflow.json file or a Kleinflow PNG (Ctrl O)"
          >
            Open…
          </button>
          <button
            type="button"
            className="kf-button"
            onClick={p.onRecent}
            aria-haspopup="dialog"
            title="Reopen a document this browser saved, from any tab"
          >
            Recent
          </button>
          <button
            type="button"
            className="kf-button"
            onClick={p.onSave}
            title="Download the graph as .kleinflow.json (Ctrl S)"
          >
            Save
          </button>
          <Menu label="Export" title="Export a picture or the shader" items={p.exportItems} />
          <PresentButton onPresent={p.onPresent} />
          <span className="kf-toolbar__gap" />
          <button
            type="button"
            className={`kf-button${p.inspecting ? ' kf-button--active' : ''}`}
            onClick={p.onInspect}
            aria-pressed={p.inspecting}
            aria-label="Inspect"
            title="Inspect: click a point of the picture to see its orbit, step by step (Alt-click works any time; Esc leaves)"
          >
            <svg viewBox="0 0 16 16" width="14" height="14" aria-hidden="true">
              <circle cx="8" cy="8" r="4.5" fill="none" stroke="currentColor" strokeWidth="1.5" />
              <path d="M8 0.5v3M8 12.5v3M0.5 8h3M12.5 8h3" stroke="currentColor" strokeWidth="1.5" />
            </svg>
            <span className="kf-toolbar__label">Inspect</span>
          </button>
          <button
            type="button"
            className="kf-button kf-button--icon"
            onClick={p.onUndo}
            disabled={!p.undoLabel}
            aria-label="Undo"
            title={p.undoLabel ? `Undo ${p.undoLabel} (Ctrl Z)` : 'Nothing to undo'}
          >
            ↶
          </button>
          <button
            type="button"
            className="kf-button kf-button--icon"
            onClick={p.onRedo}
            disabled={!p.redoLabel}
            aria-label="Redo"
            title={p.redoLabel ? `Redo ${p.redoLabel} (Ctrl Y)` : 'Nothing to redo'}
          >
            ↷
          </button>
          <button
            type="button"
            className={`kf-button kf-button--icon${p.playing ? ' kf-button--active' : ''}`}
            onClick={p.onPlay}
            aria-label={p.playing ? 'Pause animation' : 'Play animation'}
            title={p.playing ? 'Pause animation time' : 'Play animation time (nodes may read time)'}
          >
            {p.playing ? '❚❚' : '▶'}
          </button>
          <button
            type="button"
            className="kf-button kf-button--icon"
            onClick={p.onHelp}
            aria-label="Help"
            title="Help and shortcuts (?)"
          >
            ?
          </button>
        </nav>
      )}
    </header>
  );
}
